// mesh_samples.hpp - what the mesh suites share: uniform random points in
// the unit square, and a mesh's layout (every record and entry edge, word for
// word) for comparing how two meshes were built.
#ifndef PDS_TEST_MESH_SAMPLES_HPP
#define PDS_TEST_MESH_SAMPLES_HPP

#include <cstdint>
#include <random>
#include <vector>

#include "mesh/delaunay.hpp"

inline std::vector<pds::Point> random_points(std::size_t n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<pds::Point> pts(n);
    for (pds::Point& p : pts) p = {u(rng), u(rng)};
    return pts;
}

// Every record (origins and links; a free record as kNoVertex alone), then
// every entry edge.
inline std::vector<std::uint32_t> layout_of(const pds::Delaunay& dt) {
    std::vector<std::uint32_t> words;
    const pds::QuadEdgeMesh& m = dt.mesh();
    for (std::size_t r = 0; r < m.record_count(); ++r) {
        const pds::EdgeRef e = static_cast<pds::EdgeRef>(4 * r);
        words.push_back(m.is_live(r) ? m.org(e) : pds::kNoVertex);
        if (!m.is_live(r)) continue;
        words.push_back(m.dest(e));
        for (pds::EdgeRef q = 0; q < 4; ++q) words.push_back(m.onext(e + q));
    }
    for (std::size_t v = 0; v < dt.vertex_count(); ++v) words.push_back(dt.edge_of(static_cast<std::uint32_t>(v)));
    return words;
}

#endif
