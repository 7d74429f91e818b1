// verify_torus.hpp - the certificate of verify.hpp for a periodic pattern.
//
// From the mesh's points and structure only, exactly:
//   - every real point inside the fundamental domain and on the torus grid;
//   - every pair at least R apart on the torus (each point against every
//     copy of its neighbours, through a wrapped grid, not the mesh);
//   - the copies in the mesh exactly the copies of the points inside the
//     margin region, the mesh consistent and Delaunay, and every triangle
//     around a real point with its circumdisk inside that region: then the
//     real points' cells are their cells on the torus (torus_copies.hpp);
//   - maximality: every Voronoi vertex of every real point within R of it
//     (the cells tile the torus, so nothing else can be uncovered).
#ifndef PDS_VERIFY_TORUS_HPP
#define PDS_VERIFY_TORUS_HPP

#include <cstdint>
#include <vector>

#include "mesh/delaunay.hpp"
#include "mesh/torus_copies.hpp"
#include "verify/verify.hpp"

namespace pds {

// is_copy[v] != 0 marks the mesh's copies.
// A variable radius (a weighted mesh): radius is the largest and rank[v] the
// place of real vertex v in the order the points were added; each point must
// lie outside every earlier point's disk (every copy of it), and maximality
// is judged on the power diagram.
VerifyReport verify_torus(const Delaunay& dt, const TorusCopies& copies, const std::vector<std::uint8_t>& is_copy,
                          double radius, const std::vector<std::size_t>* rank = nullptr);

}  // namespace pds

#endif
