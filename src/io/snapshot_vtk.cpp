// Snapshot PolyData of grains, contacts and walls, and the writer that keeps
// the .pvd collections (see snapshot_vtk.h).
#include "io/snapshot_vtk.h"

#include "core/error.h"
#include "core/parallel.h"
#include "geometry/primitives.h"
#include "io/pvd_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace grainlab {

namespace {

// Values of a per-grain array repeated on each of that grain's points:
// grain i covers points [first[i], first[i+1]).
template <typename T>
std::vector<T> broadcast(const std::vector<T>& per_grain, int components, const std::vector<std::size_t>& first) {
  const std::size_t n = first.size() - 1;
  const std::size_t c = static_cast<std::size_t>(components);
  std::vector<T> out(first.back() * c);
  parallel_for(static_cast<std::ptrdiff_t>(n), [&](std::ptrdiff_t i) {
    for (std::size_t p = first[i]; p < first[i + 1]; ++p)
      std::copy_n(per_grain.begin() + i * c, c, out.begin() + p * c);
  });
  return out;
}

std::vector<double> flatten(const std::vector<Vec3>& v) {
  std::vector<double> out(3 * v.size());
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int k = 0; k < 3; ++k) out[3 * i + k] = v[i][k];
  return out;
}

// Float64 values as Float32 (other types unchanged).
void to_float32(VtkArray& a) {
  if (const auto* d = std::get_if<std::vector<double>>(&a.values))
    a.values = std::vector<float>(d->begin(), d->end());
}

template <typename T>
void check_size(const std::vector<T>& v, std::size_t n, const char* name) {
  if (!v.empty() && v.size() != n)
    throw std::invalid_argument(fmt::format("grain field '{}' has {} entries for {} grains", name, v.size(), n));
}

void check_matches(const Model& model, const State& state) {
  if (state.bodies.size() != model.bodies.size() || state.walls.size() != model.walls.size())
    throw std::invalid_argument(fmt::format("the State ({} grains, {} walls) does not belong to the Model ({} grains, "
                                            "{} walls)",
                                            state.bodies.size(), state.walls.size(), model.bodies.size(),
                                            model.walls.size()));
}

// Side (m) of the square drawn for plane walls: twice the largest extent of the grains' bounding spheres.
double auto_plane_size(const Model& model, const State& state) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (std::size_t i = 0; i < state.bodies.size(); ++i) {
    const double r = model.bodies[i].bounding_radius;
    lo = lo.cwiseMin(state.bodies[i].x - Vec3::Constant(r));
    hi = hi.cwiseMax(state.bodies[i].x + Vec3::Constant(r));
  }
  const double extent = state.bodies.empty() ? 0.0 : (hi - lo).maxCoeff();
  return extent > 0 && std::isfinite(extent) ? 2 * extent : 1e-2;
}

}  // namespace

double snapshot_rotation_angle(const Quat& now, const Quat& ref) {
  const Quat dq = now * ref.inverse();
  return 2 * std::atan2(dq.vec().norm(), std::abs(dq.w()));
}

std::vector<std::int32_t> grain_contact_counts(const State& state) {
  std::vector<std::int32_t> n(state.bodies.size(), 0);
  for_each_touching_pair(state.contacts, [&n](Index a, Index b) {
    ++n[a];
    ++n[b];
  });
  return n;
}

GrainFields grain_fields(const State& state, const State* reference) {
  const std::size_t n = state.bodies.size();
  GrainFields f;
  f.velocity.resize(n);
  for (std::size_t i = 0; i < n; ++i) f.velocity[i] = state.bodies[i].v;
  f.coordination = grain_contact_counts(state);
  if (reference) {
    if (reference->bodies.size() != n)
      throw std::invalid_argument(fmt::format("the reference State has {} grains, the current one {}",
                                              reference->bodies.size(), n));
    f.displacement.resize(n);
    f.rotation.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      f.displacement[i] = state.bodies[i].x - reference->bodies[i].x;
      f.rotation[i] = snapshot_rotation_angle(state.bodies[i].q, reference->bodies[i].q);
    }
  }
  return f;
}

PolyData grains_polydata(const Model& model, const State& state, const GrainFields& fields,
                         const SnapshotOptions& options) {
  check_matches(model, state);
  const std::size_t n = state.bodies.size();
  check_size(fields.displacement, n, "displacement");
  check_size(fields.rotation, n, "rotation");
  check_size(fields.velocity, n, "velocity");
  check_size(fields.coordination, n, "coordination");
  for (const VtkArray& a : fields.extra)
    if (a.components < 1 || a.value_count() != n * static_cast<std::size_t>(a.components))
      throw std::invalid_argument(fmt::format("extra grain array '{}' has {} values, expected {} grains x {}", a.name,
                                              a.value_count(), n, a.components));

  // Each shape's surface at scale 1 in its principal frame; spheres as icospheres.
  std::vector<TriMesh> sphere_mesh(model.shapes.size());
  std::vector<const TriMesh*> mesh(model.shapes.size());
  for (std::size_t s = 0; s < model.shapes.size(); ++s) {
    const Shape& shape = model.shapes[s];
    if (shape.kind == Shape::Kind::Sphere) {
      sphere_mesh[s] = icosphere(shape.equivalent_radius, options.sphere_subdivisions);
      mesh[s] = &sphere_mesh[s];
    } else {
      mesh[s] = &shape.mesh;
    }
  }

  // Grain i owns points [first_point[i], first_point[i+1]) and triangles [first_face[i], first_face[i+1]).
  std::vector<std::size_t> first_point(n + 1, 0), first_face(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const TriMesh& m = *mesh[model.bodies[i].shape];
    first_point[i + 1] = first_point[i] + m.vertices.size();
    first_face[i + 1] = first_face[i] + m.faces.size();
  }

  PolyData pd;
  std::vector<double> points(3 * first_point[n]);
  pd.polys.connectivity.resize(3 * first_face[n]);
  pd.polys.offsets.resize(first_face[n]);
  parallel_for(static_cast<std::ptrdiff_t>(n), [&](std::ptrdiff_t i) {
    const TriMesh& m = *mesh[model.bodies[i].shape];
    const BodyState& b = state.bodies[i];
    const Mat3 r = b.q.toRotationMatrix() * model.bodies[i].scale;
    for (std::size_t v = 0; v < m.vertices.size(); ++v) {
      const Vec3 p = b.x + r * m.vertices[v];
      for (int k = 0; k < 3; ++k) points[3 * (first_point[i] + v) + k] = p[k];
    }
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
      const std::size_t c = first_face[i] + f;
      for (int k = 0; k < 3; ++k)
        pd.polys.connectivity[3 * c + k] = static_cast<std::int64_t>(first_point[i]) + m.faces[f][k];
      pd.polys.offsets[c] = static_cast<std::int64_t>(3 * (c + 1));
    }
  });
  pd.points.values = std::move(points);

  std::vector<std::int32_t> ids(n);
  for (std::size_t i = 0; i < n; ++i) ids[i] = static_cast<std::int32_t>(i);
  pd.point_data.push_back({"grain_id", 1, broadcast(ids, 1, first_point)});
  if (!fields.displacement.empty())
    pd.point_data.push_back({"displacement", 3, broadcast(flatten(fields.displacement), 3, first_point)});
  if (!fields.rotation.empty()) pd.point_data.push_back({"rotation", 1, broadcast(fields.rotation, 1, first_point)});
  if (!fields.velocity.empty())
    pd.point_data.push_back({"velocity", 3, broadcast(flatten(fields.velocity), 3, first_point)});
  if (!fields.coordination.empty())
    pd.point_data.push_back({"coordination", 1, broadcast(fields.coordination, 1, first_point)});
  for (const VtkArray& a : fields.extra) {
    VtkArray out{a.name, a.components, {}};
    std::visit([&](const auto& v) { out.values = broadcast(v, a.components, first_point); }, a.values);
    pd.point_data.push_back(std::move(out));
  }

  if (options.single_precision) {
    to_float32(pd.points);
    for (VtkArray& a : pd.point_data) to_float32(a);
  }
  return pd;
}

PolyData contacts_polydata(const State& state) {
  PolyData pd;
  std::vector<double> points;
  std::vector<std::int32_t> grain_a, grain_b, sub;
  std::vector<double> magnitude, normal_force, tangential, normal, force;
  for (const Contact& pc : state.contacts) {
    if (!in_contact(pc)) continue;
    const Index base = static_cast<Index>(points.size() / 3);
    for (const Vec3& x : {state.bodies[pc.a].x, state.bodies[pc.b].x}) points.insert(points.end(), x.data(), x.data() + 3);
    pd.lines.add({base, base + 1});
    grain_a.push_back(pc.a);
    grain_b.push_back(pc.b);
    sub.push_back(pc.sub);
    const Vec3& n = pc.geo.normal;
    magnitude.push_back(pc.force.norm());
    normal_force.push_back(pc.normal_force);
    // The law returns f_n n + f_t with f_t in the tangent plane.
    tangential.push_back((pc.force - pc.force.dot(n) * n).norm());
    normal.insert(normal.end(), n.data(), n.data() + 3);
    force.insert(force.end(), pc.force.data(), pc.force.data() + 3);
  }
  pd.points.values = std::move(points);
  pd.cell_data.push_back({"grain_a", 1, std::move(grain_a)});
  pd.cell_data.push_back({"grain_b", 1, std::move(grain_b)});
  pd.cell_data.push_back({"sub_contact", 1, std::move(sub)});
  pd.cell_data.push_back({"force_magnitude", 1, std::move(magnitude)});
  pd.cell_data.push_back({"normal_force", 1, std::move(normal_force)});
  pd.cell_data.push_back({"tangential_force", 1, std::move(tangential)});
  pd.cell_data.push_back({"normal", 3, std::move(normal)});
  pd.cell_data.push_back({"force", 3, std::move(force)});
  return pd;
}

PolyData walls_polydata(const Model& model, const State& state, const SnapshotOptions& options) {
  check_matches(model, state);
  const double half_patch = 0.5 * (options.plane_size > 0 ? options.plane_size : auto_plane_size(model, state));
  PolyData pd;
  std::vector<double> points;
  std::vector<std::int32_t> wall_id;
  std::vector<double> force;
  for (std::size_t w = 0; w < model.walls.size(); ++w) {
    const WallModel& wm = model.walls[w];
    const WallState& ws = state.walls[w];
    TriMesh local;
    if (wm.kind == WallModel::Kind::Box) {
      local = box_mesh(wm.half.x(), wm.half.y(), wm.half.z());
    } else {
      // A square in the plane's local xy, counter-clockwise seen from +z (the outward normal).
      const double h = half_patch;
      local.vertices = {Vec3(-h, -h, 0), Vec3(h, -h, 0), Vec3(h, h, 0), Vec3(-h, h, 0)};
      local.faces = {Face{0, 1, 2}, Face{0, 2, 3}};
    }
    const Index base = static_cast<Index>(points.size() / 3);
    for (const Vec3& v : local.vertices) {
      const Vec3 p = ws.x + ws.q * v;
      points.insert(points.end(), p.data(), p.data() + 3);
    }
    for (const Face& f : local.faces) {
      pd.polys.add({base + f[0], base + f[1], base + f[2]});
      wall_id.push_back(static_cast<std::int32_t>(w));
      force.insert(force.end(), ws.force.data(), ws.force.data() + 3);
    }
  }
  pd.points.values = std::move(points);
  pd.cell_data.push_back({"wall_id", 1, std::move(wall_id)});
  pd.cell_data.push_back({"force", 3, std::move(force)});
  return pd;
}

SnapshotWriter::SnapshotWriter(std::filesystem::path folder, SnapshotOptions options)
    : folder_(std::move(folder)),
      options_(options),
      grains_(folder_ / "grains.pvd"),
      contacts_(folder_ / "contacts.pvd"),
      walls_(folder_ / "walls.pvd") {
  std::error_code ec;
  std::filesystem::create_directories(folder_, ec);
  if (ec)
    throw RunError(fmt::format("cannot create the output folder '{}': {}. Check the path and its permissions",
                               folder_.string(), ec.message()));
}

void SnapshotWriter::keep_existing_collections() {
  for (PvdCollection* c : {&grains_, &contacts_, &walls_}) {
    if (!std::filesystem::exists(c->path())) continue;
    for (const PvdEntry& e : read_pvd(c->path())) c->add(e.time, e.file);
  }
}

std::string SnapshotWriter::file_name(std::string_view kind, int index) {
  if (index < 0) throw std::invalid_argument(fmt::format("snapshot index {} is negative", index));
  return fmt::format("{}_{:04d}.vtp", kind, index);
}

void SnapshotWriter::write(int index, double time, const Model& model, const State& state, const GrainFields& fields) {
  if (!std::isfinite(time)) throw std::invalid_argument(fmt::format("snapshot time {} is not finite", time));
  const std::string grains = file_name("grains", index), contacts = file_name("contacts", index),
                    walls = file_name("walls", index);
  // All three data files first, then the collections: a .pvd never lists a missing file.
  write_vtp(folder_ / grains, grains_polydata(model, state, fields, options_));
  write_vtp(folder_ / contacts, contacts_polydata(state));
  write_vtp(folder_ / walls, walls_polydata(model, state, options_));
  grains_.add(time, grains);
  contacts_.add(time, contacts);
  walls_.add(time, walls);
  if (!have_first_) {
    first_.bodies = state.bodies;
    have_first_ = true;
  }
}

void SnapshotWriter::write(int index, double time, const Model& model, const State& state, const State* reference) {
  if (!reference) reference = have_first_ ? &first_ : &state;
  write(index, time, model, state, grain_fields(state, reference));
}

}  // namespace grainlab
