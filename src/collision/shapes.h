// Convex shapes as support mappings, in world space, for GJK/EPA and the
// analytic routines. Pure geometry: no bodies, no masses.
//
// Every shape type S offers
//   Vec3 support(const Vec3& d) const;  // a point of S maximising dot(p, d)
//   Vec3 center() const;                // a point strictly inside S
#pragma once

#include "core/types.h"

#include <vector>

namespace grainlab {

// A convex polytope in its own (local) frame, with the vertex adjacency that
// support queries hill-climb on. Built once per grain shape, shared by all grains.
class ConvexPolytope {
 public:
  ConvexPolytope() = default;
  ConvexPolytope(std::vector<Vec3> vertices, std::vector<Index> adjacency_offsets,
                 std::vector<Index> adjacency);

  // Index of a vertex maximising dot(v, d), found by hill climbing from `start`.
  Index support_index(const Vec3& d, Index start) const;

  const std::vector<Vec3>& vertices() const { return vertices_; }
  const Vec3& vertex(Index i) const { return vertices_[i]; }
  std::size_t size() const { return vertices_.size(); }
  // Bytes held by the polytope's arrays (its collision data's memory).
  std::size_t memory_bytes() const {
    return vertices_.size() * sizeof(Vec3) + (offsets_.size() + adjacency_.size()) * sizeof(Index) +
           planes_.size() * sizeof(Plane) + (plane_offsets_.size() + vertex_planes_.size()) * sizeof(Index) +
           is_edge_.size();
  }
  // Neighbours of vertex v.
  const Index* neighbours_begin(Index v) const { return adjacency_.data() + offsets_[v]; }
  const Index* neighbours_end(Index v) const { return adjacency_.data() + offsets_[v + 1]; }
  double bounding_radius() const { return bounding_radius_; }  // max |v| in the local frame

  // Face planes (outward unit normal m, offset c: inside is m.x <= c), found
  // from the vertex graph at construction, coplanar triangles merged. Each
  // vertex lists the planes through it. Used to measure how deep a point lies
  // inside the polytope near a contact (patch.cpp).
  struct Plane {
    Vec3 m;
    double c;
  };
  const std::vector<Plane>& planes() const { return planes_; }
  const Index* planes_begin(Index v) const { return vertex_planes_.data() + plane_offsets_[v]; }
  const Index* planes_end(Index v) const { return vertex_planes_.data() + plane_offsets_[v + 1]; }
  // Whether the neighbour entry `it` (from neighbours_begin(v)..end(v)) is an
  // edge of the polytope: v and it share two face planes. False for the
  // diagonal of a face whose coplanar triangles merged into one plane.
  bool is_edge(const Index* it) const { return is_edge_[static_cast<std::size_t>(it - adjacency_.data())] != 0; }

 private:
  void build_planes();

  std::vector<Vec3> vertices_;
  std::vector<Index> offsets_;
  std::vector<Index> adjacency_;
  double bounding_radius_ = 0;
  std::vector<Plane> planes_;
  std::vector<Index> plane_offsets_;
  std::vector<Index> vertex_planes_;
  std::vector<unsigned char> is_edge_;  // per adjacency entry
};

// A ConvexPolytope placed in the world: p_world = pos + rot * (scale * p_local).
// `hint` is the vertex the last support query ended on; callers may seed it
// (from a per-pair cache) and read it back.
struct PolytopeShape {
  const ConvexPolytope* poly = nullptr;
  Mat3 rot = Mat3::Identity();
  Vec3 pos = Vec3::Zero();
  double scale = 1;
  mutable Index hint = 0;

  Vec3 support(const Vec3& d) const {
    hint = poly->support_index(rot.transpose() * d, hint);
    return pos + scale * (rot * poly->vertex(hint));
  }
  Vec3 point(Index i) const { return pos + scale * (rot * poly->vertex(i)); }  // vertex i in the world
  Vec3 center() const { return pos; }
};

struct SphereShape {
  Vec3 pos = Vec3::Zero();
  double radius = 0;

  Vec3 support(const Vec3& d) const {
    const double n = d.norm();
    return n > 0 ? Vec3(pos + (radius / n) * d) : Vec3(pos + Vec3(radius, 0, 0));
  }
  Vec3 center() const { return pos; }
};

// An oriented box: p_world = pos + rot * p_local, |p_local_i| <= half_i.
struct BoxShape {
  Mat3 rot = Mat3::Identity();
  Vec3 pos = Vec3::Zero();
  Vec3 half = Vec3::Ones();

  Vec3 support(const Vec3& d) const {
    const Vec3 dl = rot.transpose() * d;
    const Vec3 p(dl.x() >= 0 ? half.x() : -half.x(), dl.y() >= 0 ? half.y() : -half.y(),
                 dl.z() >= 0 ? half.z() : -half.z());
    return pos + rot * p;
  }
  Vec3 center() const { return pos; }
};

// A half-space wall: solid on the side opposite `normal`; grains live where
// dot(x - point, normal) > 0.
struct PlaneShape {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();  // unit
};

}  // namespace grainlab
