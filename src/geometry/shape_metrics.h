// Shape of a grain in numbers: size, principal dimensions, sphericity,
// convexity and Wadell roundness (the Zheng & Hryciw way, on projection
// outlines). See docs/grains.md for the definitions and the method.
#pragma once

#include "geometry/trimesh.h"

#include <array>
#include <span>
#include <vector>

namespace grainlab {


// Shape descriptors of one closed, outward mesh. Lengths in the mesh's units (m).
struct ShapeMetrics {
  double volume = 0;               // m^3
  double surface_area = 0;         // m^2
  double equivalent_diameter = 0;  // m: diameter of the sphere of equal volume
  double long_axis = 0;            // m: L, the largest extent along a principal axis of inertia
  double intermediate_axis = 0;    // m: I
  double short_axis = 0;           // m: S
  double elongation = 0;           // I / L (1 = not elongated)
  double flatness = 0;             // S / I (1 = not flat)
  double sphericity = 0;           // true sphericity: area of the equal-volume sphere / surface area
  double convexity = 0;            // volume / convex hull volume
  double roundness = 0;            // Wadell roundness, mean over the three principal projections
  std::array<double, 3> projection_roundness{};  // on the planes (L,I), (L,S), (I,S)
};

// The principal frame of a mesh: centroid and axes of inertia ordered by extent.
struct PrincipalFrame {
  Vec3 centroid = Vec3::Zero();
  Mat3 axes = Mat3::Identity();  // columns: long, intermediate, short axis; right-handed
  Vec3 extents = Vec3::Zero();   // L >= I >= S: vertex extent along each column of `axes`
};

// Centroid and principal axes (mass_properties), with extents measured along them.
PrincipalFrame principal_frame(const TriMesh& mesh);

// Moves the mesh's centroid to the origin and its principal axes (long,
// intermediate, short) to x, y, z.
void move_to_principal_frame(TriMesh& mesh);

// All descriptors of a closed, outward mesh (one that passes check_mesh).
ShapeMetrics shape_metrics(const TriMesh& mesh);

// --- 2D outlines (closed polygons, counter-clockwise, no repeated last point) ---

// Convex hull of 2D points, counter-clockwise (Andrew's monotone chain).
std::vector<Vec2> convex_outline(std::span<const Vec2> points);

// Outer boundary of the union of the triangles (points[f[0]], points[f[1]],
// points[f[2]]): the silhouette of a possibly non-convex solid. Counter-clockwise.
// The triangles are rasterised with 4 x 4 samples per pixel, `resolution`
// pixels across the larger side, and the outline is traced where the coverage
// is 1/2 (marching squares, crossings interpolated): within a fifth of a
// pixel of the true boundary, with its length, not a pixel staircase.
std::vector<Vec2> silhouette_outline(std::span<const Vec2> points, std::span<const Face> faces,
                                     int resolution = 512);

// Radius of the largest circle inside a closed outline (any simple polygon);
// its centre goes to *centre when given.
double largest_inscribed_circle(std::span<const Vec2> outline, Vec2* centre = nullptr);

// Wadell roundness of one outline and the numbers it comes from.
struct OutlineRoundness {
  double roundness = 1;           // mean corner radius / inscribed radius, capped at 1
  double inscribed_radius = 0;    // radius of the largest inscribed circle
  double mean_corner_radius = 0;  // 0 when no corner was found
  int corners = 0;                // corner circles fitted
};

// Zheng & Hryciw's procedure on one outline: resample, smooth, find corners
// (convex stretches whose curvature radius is below the inscribed radius), fit a
// circle to each corner, and divide the mean corner radius by the inscribed radius.
OutlineRoundness outline_roundness(std::span<const Vec2> outline);

}  // namespace grainlab
