// point_order.hpp - the user's point order against the mesh's vertex order.
//
// Points keep the order they were added in (every prefix is a Poisson-disk
// pattern). The Jones stage numbers its own vertices in that order, but the
// dart stage's points enter the mesh at the hand-over sorted along a curve
// for locality: for those, and only those, a table gives the vertex.
//   point k  ->  vertex_[k]             for k < handed_over()
//            ->  k + kGhostVertices     after
// On the torus, copies take vertices between the points, so every point is
// recorded (push).
#ifndef PDS_POINT_ORDER_HPP
#define PDS_POINT_ORDER_HPP

#include <cstddef>
#include <vector>

#include "core/indices.hpp"

namespace pds {

class PointOrder {
public:
    void reserve(std::size_t points) { vertex_.reserve(points); }
    std::size_t capacity() const { return vertex_.capacity(); }
    // Records that point k went to vertex v (hand-over; requires capacity).
    void resize(std::size_t handed_over) { vertex_.resize(handed_over); }
    void set(PointIndex k, VertexIndex v) { vertex_[k] = v; }
    // Records the next point's vertex (the torus; requires capacity).
    void push(VertexIndex v) { vertex_.push_back(v); }
    // Records the implicit vertices of the first `points` points, so that
    // the next ones may be recorded (requires capacity).
    void extend_to(std::size_t points) {
        while (vertex_.size() < points) vertex_.push_back(static_cast<VertexIndex>(vertex_.size() + kGhostVertices));
    }
    std::size_t handed_over() const { return vertex_.size(); }

    VertexIndex vertex(PointIndex k) const {
        return k < vertex_.size() ? vertex_[k] : static_cast<VertexIndex>(k + kGhostVertices);
    }
    // O(handed over): for error messages only.
    PointIndex point(VertexIndex v) const {
        for (std::size_t k = 0; k < vertex_.size(); ++k)
            if (vertex_[k] == v) return k;
        return static_cast<PointIndex>(v - kGhostVertices);
    }

private:
    std::vector<VertexIndex> vertex_;
};

}  // namespace pds

#endif
