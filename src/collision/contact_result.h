// What every narrowphase routine returns for a pair of shapes A and B.
#pragma once

#include "core/types.h"

namespace grainlab {

struct ContactResult {
  bool touching = false;  // shapes overlap (depth > 0)
  double depth = 0;       // overlap if touching, else minus the separation distance, or a lower
                          // bound of it for shapes found far apart (penetration.h) (m)
  Vec3 normal = Vec3::UnitZ();  // unit, points from A towards B: moving B by depth*normal separates them
  Vec3 point = Vec3::Zero();    // contact point, midway between the two surfaces (m)
  // Spread of an extended contact patch: the depth-weighted mean squared
  // distance of the penetrating vertices from `point` (m^2); 0 for a point
  // contact. Lets the contact law damp rocking of a face lying on a wall.
  double spread = 0;
  // Faceted contacts (collision/soft_depth.h): the law's elastic force at
  // `depth` times `gain` is the pair's elastic force (1 for a point contact),
  // and `twist` times the law's elastic force (N) is a torque on B (N m)
  // beyond that of the force at `point` (zero for a face on a plane) (m).
  double gain = 1;
  Vec3 twist = Vec3::Zero();
  // The share of one contact this result carries (0 to 1): a contact of two
  // concave grains found once per piece pair along a seam is split among its
  // results (weigh_seams, routines_compound.cpp), which also scales `gain`
  // and `twist`. The law scales the contact's damping and tangential spring
  // by it, so the results of one contact add up to one contact in every
  // term, not in the elastic force alone; 1 for every convex pair.
  double share = 1;
};

}  // namespace grainlab
