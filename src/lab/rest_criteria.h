// When is a specimen at rest? The measures the lab's phases test, and the
// counting that turns single checks into "at rest".
//
//  * Kinetic energy small against the elastic energy stored in the contacts:
//    E_k < 1e-2 E_el, with E_el the contact law's elastic energy summed over
//    the contacts (Hertz: f = K delta^{3/2}, so the work int f d(delta) =
//    (2/5) f delta; Hooke: (1/2) f delta). E_k leaves out the spin of a
//    sphere that no contact can brake: a contact's normal force passes
//    through a sphere's centre, and a point contact's friction acts only on
//    the slip at the point, which a spin about the contact's own normal does
//    not make. So a sphere's spin is left out whole when it has no
//    frictional contact, and its component along the line of its frictional
//    contacts when they all lie on one line (one contact, or two opposite):
//    nothing acts on it, it never decays and it moves nothing. Measured: a
//    bead on the lubricated floor spinning at 805 rad/s held 94 % of a
//    packing's kinetic energy at an unbalanced ratio of 7e-12, and the Dr 0.3
//    preparation never ended; a bead among three frictionless walls and one
//    frictional grain contact spun at 511 rad/s about that contact's normal
//    (to 1e-11) and held all of a triaxial compaction's kinetic energy.
//  * Unbalanced-force ratio: mean |resultant| per grain over the mean
//    |contact force| (1 with no contacts). Averaged: each grain's resultant
//    is first averaged over the steps of a window (ForceWindow; the direct
//    shear's spans the current calm run, up to 1000 steps): the static
//    imbalance, without the ringing of stiff contacts and of the packing's
//    collective modes, which keeps the instantaneous ratio of faceted grains
//    at 0.1-0.2 in a packing at rest.
//  * Calm checks: a check every kCheckEvery steps; kCalmChecks consecutive
//    calm checks mean at rest (CalmCounter).
#pragma once

#include "core/bytes.h"
#include "dynamics/world.h"

#include <cstdint>
#include <vector>

namespace grainlab {

inline constexpr int kCheckEvery = 50;  // steps between rest checks
inline constexpr int kCalmChecks = 20;  // consecutive calm checks = at rest

// Elastic energy stored in the touching contacts (J), by the model's contact law.
double contact_elastic_energy(const Model& m, const State& s);
// Kinetic energy of the bodies (J), less the spin of spheres that no
// contact can brake (above; the friction in effect, overrides included).
double packing_kinetic_energy(const World& w);
// That kinetic energy below 1e-2 of the contacts' elastic energy.
bool kinetic_small_against_elastic(const World& w);
// force over the mean magnitude of the contact forces (1 with no contacts).
double per_mean_contact_force(const State& s, double force);
// Mean |resultant| per grain over the mean |contact force|, this step.
double unbalanced_force_ratio(const World& w);

// Each grain's resultant force summed over a check window.
class ForceWindow {
 public:
  // Adds this step's resultants (World::body_forces()).
  void add(const std::vector<Vec3>& forces);
  // Starts a new window.
  void reset();
  // Steps summed so far.
  int steps() const { return steps_; }
  // The unbalanced-force ratio of the window's mean resultants (the
  // instantaneous one if the window is empty).
  double averaged_ratio(const World& w) const;
  // The window's state, little-endian.
  void save(ByteWriter& out) const;
  void load(ByteReader& in);

 private:
  std::int32_t steps_ = 0;    // steps summed in sum_
  std::vector<Vec3> sum_;     // N, per grain
};

// Counts consecutive calm checks.
class CalmCounter {
 public:
  // Records one check; true once kCalmChecks consecutive checks were calm.
  bool check(bool calm) {
    count_ = calm ? count_ + 1 : 0;
    return count_ >= kCalmChecks;
  }
  void reset() { count_ = 0; }
  // Consecutive calm checks so far.
  int count() const { return count_; }
  void save(ByteWriter& out) const { out.i32(count_); }
  void load(ByteReader& in) { count_ = in.i32(); }

 private:
  std::int32_t count_ = 0;
};

// A run of rest checks: consecutive calm checks, and each grain's resultant
// summed over the run. At rest: kCalmChecks calm checks in a row and the
// run's averaged unbalanced-force ratio at most max_unbalanced (else the run
// starts again). The window spans the whole calm run rather than one check
// interval because a packing rings in collective modes longer than 50 steps:
// in the tiny test box the ratio averaged over 50 steps swings up to 0.014
// while over 1000 steps it is 0.0008.
class RestRun {
 public:
  // Adds this step's resultants (World::body_forces()).
  void add(const std::vector<Vec3>& forces) { window_.add(forces); }
  // One check (every kCheckEvery steps): `calm` is the test's own criterion
  // (its stresses, its kinetic energy); the balance is asked only when
  // check_balance. True when at rest.
  bool check(bool calm, const World& w, double max_unbalanced, bool check_balance = true) {
    bool rest = calm_.check(calm);
    last_ratio_ = window_.averaged_ratio(w);
    last_steps_ = window_.steps();
    if (rest && check_balance && last_ratio_ > max_unbalanced) {
      calm_.reset();
      rest = false;
    }
    if (calm_.count() == 0 || rest) window_.reset();
    return rest;
  }
  // A new phase: the calm count starts again (the window at the next check).
  void restart() { calm_.reset(); }
  // A new phase, window included.
  void reset() {
    calm_.reset();
    window_.reset();
  }
  // The averaged ratio and the window's steps at the last check (for messages).
  double last_ratio() const { return last_ratio_; }
  int last_steps() const { return last_steps_; }
  // The run's state (the calm count, then the window), little-endian.
  void save(ByteWriter& out) const {
    calm_.save(out);
    window_.save(out);
  }
  void load(ByteReader& in) {
    calm_.load(in);
    window_.load(in);
  }

 private:
  CalmCounter calm_;
  ForceWindow window_;
  double last_ratio_ = 0;
  int last_steps_ = 0;
};

}  // namespace grainlab
