// World: a Model, its State, and the step that advances them.
//
// World::step(dt) is a short recipe of named phases (docs/architecture.md
// "The step"), each in its own file: collision_driver.h (bounds, broadphase,
// narrowphase), contact_forces.h (forces), integrator.h (integrate); the
// time-step guard and the thread choice are step_guard.h's:
//   bounds -> broadphase -> narrowphase -> forces -> controllers -> integrate
//   -> bookkeeping,
// each timed into `profile`. Lab protocols hook in as controllers (called after
// the forces, before integration: they read wall forces and set wall
// velocities); the step itself does no I/O.
#pragma once

#include "collision/posed_shape.h"
#include "core/thread_tuner.h"
#include "dynamics/collision_driver.h"
#include "dynamics/model.h"
#include "dynamics/profile.h"
#include "dynamics/state.h"
#include "dynamics/world_settings.h"

#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace grainlab {

// Translational plus rotational kinetic energy of one body (J).
double kinetic_energy_of(const BodyModel& m, const BodyState& s);

// Settings a lab protocol's phase lays over the Model while the phase lasts
// (deposition gravity, deposition friction): the Model itself never changes
// during a run. The step reads them; they are not part of the State (the
// protocol derives them from its phase, also after a checkpoint load).
struct PhaseOverrides {
  std::optional<Vec3> gravity;                     // m/s^2, replaces model.gravity
  std::vector<std::pair<Index, double>> friction;  // (material, Coulomb mu) replacing that material's friction
};

class World {
 public:
  using Controller = std::function<void(World&, double dt)>;

  Model model;
  State state;
  StepProfile profile;
  WorldSettings settings;  // skin, critical-step overlap, threads

  World() = default;
  explicit World(Model m) : model(std::move(m)) {}

  // Adds a grain at centre of mass x with orientation q (local principal
  // frame to world), velocity v and angular velocity w.
  Index add_body(Index shape, Index material, double scale, const Vec3& x,
                 const Quat& q = Quat::Identity(), const Vec3& v = Vec3::Zero(),
                 const Vec3& w = Vec3::Zero());
  // A half-space wall through `point` with outward unit `normal` (grains live on that side).
  Index add_plane(const Vec3& point, const Vec3& normal, Index material = 0, std::string name = "plane");
  // A solid box wall.
  Index add_box_wall(const Vec3& center, const Vec3& half, const Quat& q = Quat::Identity(),
                     Index material = 0, std::string name = "box");
  void add_controller(Controller c) { controllers_.push_back(std::move(c)); }

  // Lays phase settings over the Model (replacing any earlier ones); friction
  // still mixes by the minimum of the two materials, as Model::finalize() does.
  void set_overrides(PhaseOverrides o);
  const PhaseOverrides& overrides() const { return overrides_; }
  // Gravity in effect: the override's, else the Model's (m/s^2).
  const Vec3& gravity() const { return overrides_.gravity ? *overrides_.gravity : model.gravity; }
  // Coefficients in effect for a material pair (the Model's, overrides applied); valid once stepped.
  const PairCoefficients& pair(Index ma, Index mb) const {
    return pair_table_[static_cast<std::size_t>(ma) * model.materials.size() + mb];
  }

  // Advances by dt seconds. Throws InputError if dt exceeds the critical
  // step, RunError if the state became non-finite.
  void step(double dt);

  // Critical time step (s) of this model (see time_step.h).
  double critical_time_step();

  // Sum of translational and rotational kinetic energy (J), inertial masses.
  double kinetic_energy() const;
  // Number of touching grain-grain and wall-grain contacts (sub-contacts) after the last step.
  std::size_t contact_count() const;
  // Number of touching grain-grain and wall-grain body pairs after the last
  // step (a pair touching at several places counts once).
  std::size_t touching_pair_count() const;
  // Resultant force and torque on each body in the last step (N, N m).
  const std::vector<Vec3>& body_forces() const { return force_; }
  const std::vector<Vec3>& body_torques() const { return torque_; }
  // Body i as the narrowphase sees it, as of the last step (for benches).
  PosedShape posed_body(Index i) const { return collisions_.posed_body(model, state, i); }
  // Threads the last step ran on, and the tuner that chose them when
  // settings.threads is 0 (core/thread_tuner.h).
  int step_threads() const { return step_threads_; }
  const ThreadTuner& thread_tuner() const { return tuner_; }

 private:
  void prepare();
  // The forces phase; `source`: the grain contacts made as it goes (else State::contacts).
  void forces(double dt, struct GrainContactSource* source);
  void integrate(double dt);
  void bookkeeping();
  void mix_pair_table();

  std::vector<Controller> controllers_;
  PhaseOverrides overrides_;
  ThreadTuner tuner_;
  int step_threads_ = 1;  // this step's thread count (settings.threads, or the tuner's)
  std::vector<PairCoefficients> pair_table_;  // model.pair() with the friction overrides
  bool prepared_ = false;
  bool prepared_once_ = false;  // prepare() has run before (the model changed since)
  double checked_dt_ = -1;  // the step last checked against the critical step
  CollisionDriver collisions_;  // bounds, broadphase, narrowphase
  std::vector<Vec3> force_, torque_;
  // |v|^2 + |w|^2 of each body after the step: finite exactly when its
  // velocities are (the step's non-finite check; cheaper than its energy).
  std::vector<double> motion_;
};

}  // namespace grainlab
