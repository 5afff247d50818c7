// Everything a run records of the contact-normal fabric of a set of grains
// (paper Eqs. 23-29, Fig. 15), in one result: the tensors of fabric.h, the
// density of kanatani.h, Psi, the unit normals, and the rose histogram and
// Kanatani grid of rose.h for plotting. Psi here is Eq. 29 on the principal
// values of phi (equal to sqrt(3/2) |D2| to rounding, fabric.h).
#pragma once

#include "analysis/fabric.h"
#include "analysis/grain_mask.h"
#include "analysis/kanatani.h"
#include "analysis/rose.h"
#include "dynamics/state.h"

#include <cstddef>
#include <vector>

namespace grainlab::analysis {

struct FabricResult {
  std::size_t contacts = 0;         // normals counted (0: the rest is left empty)
  Mat3 phi = Mat3::Zero();          // phi_ij (Eq. 27)
  KanataniDensity density;          // D2 = 15/2 dev phi, D4 = 315/8 dev phi_ijkl
  Principal principal;              // of phi, largest first
  double psi = 0;                   // Eq. 29
  std::vector<Vec3> normals;        // unit normals, contact_normals() order
  RoseHistogram rose;               // rose.h
  DensityGrid kanatani_grid;        // density sampled on rose.h's grid
};

// The fabric of the grain-grain contacts (of the grains in mask, if given;
// counting as contact_normals() does).
FabricResult fabric_result(const State& s, const GrainMask* mask = nullptr);

}  // namespace grainlab::analysis
