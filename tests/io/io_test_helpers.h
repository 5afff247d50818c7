// Shared helpers for the io tests: a temporary folder, error text, and a
// field-by-field comparison of two run specs.
#pragma once

#include <filesystem>
#include <fstream>

#include "dynamics/laws/registry.h"
#include "lab/direct_shear.h"
#include "lab/lab_spec.h"
#include "lab/oedometer.h"
#include "lab/triaxial.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <functional>
#include <string>

namespace grainlab::test {

// A fresh folder under the system temp dir, removed with everything in it.
struct IoTempDir {
  std::filesystem::path path;
  IoTempDir() {
    static std::atomic<int> counter{0};
    path = std::filesystem::temp_directory_path() /
           ("grainlab-io-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~IoTempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  IoTempDir(const IoTempDir&) = delete;
  IoTempDir& operator=(const IoTempDir&) = delete;
};

// The message of the exception of type E that f throws ("" and a failure if none).
template <typename E>
std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  ADD_FAILURE() << "no exception thrown";
  return "";
}

// True if `msg` contains `part`.
inline bool has(const std::string& msg, const std::string& part) { return msg.find(part) != std::string::npos; }

// Every field of two specs, one by one (written out by hand so that a field
// missing from the config key list shows up here).
inline void expect_same_spec(const LabSpec& a, const LabSpec& b) {
  EXPECT_EQ(a.test, b.test);
  EXPECT_EQ(a.settings<OedometerSpec>().stresses, b.settings<OedometerSpec>().stresses);
  EXPECT_EQ(a.settings<TriaxialSpec>().final_strain, b.settings<TriaxialSpec>().final_strain);
  EXPECT_EQ(a.grains.preset, b.grains.preset);
  EXPECT_EQ(a.grains.folder, b.grains.folder);
  EXPECT_EQ(a.grains.shapes, b.grains.shapes);
  EXPECT_EQ(a.grains.faces, b.grains.faces);
  EXPECT_EQ(a.grains.d_min, b.grains.d_min);
  EXPECT_EQ(a.grains.d_max, b.grains.d_max);
  EXPECT_EQ(a.material.preset, b.material.preset);
  EXPECT_EQ(a.material.law, b.material.law);
  EXPECT_EQ(a.material.grain.name, b.material.grain.name);
  EXPECT_EQ(a.material.grain.density, b.material.grain.density);
  EXPECT_EQ(a.material.grain.friction, b.material.grain.friction);
  EXPECT_EQ(a.material.grain.youngs_modulus, b.material.grain.youngs_modulus);
  EXPECT_EQ(a.material.grain.poisson_ratio, b.material.grain.poisson_ratio);
  EXPECT_EQ(a.material.grain.restitution, b.material.grain.restitution);
  EXPECT_EQ(a.material.grain.k_n, b.material.grain.k_n);
  EXPECT_EQ(a.material.grain.k_t, b.material.grain.k_t);
  EXPECT_EQ(a.material.grain.gamma_n, b.material.grain.gamma_n);
  EXPECT_EQ(a.material.grain.gamma_t, b.material.grain.gamma_t);
  EXPECT_EQ(a.material.wall_friction, b.material.wall_friction);
  EXPECT_EQ(a.box.length, b.box.length);
  EXPECT_EQ(a.box.width, b.box.width);
  EXPECT_EQ(a.box.height, b.box.height);
  EXPECT_EQ(a.box.gap, b.box.gap);
  EXPECT_EQ(a.specimen.relative_density, b.specimen.relative_density);
  EXPECT_EQ(a.specimen.e_max, b.specimen.e_max);
  EXPECT_EQ(a.specimen.e_min, b.specimen.e_min);
  EXPECT_EQ(a.specimen.void_ratio, b.specimen.void_ratio);
  EXPECT_EQ(a.specimen.tolerance, b.specimen.tolerance);
  EXPECT_EQ(a.specimen.deposition_friction, b.specimen.deposition_friction);
  EXPECT_EQ(a.specimen.from, b.specimen.from);
  EXPECT_EQ(a.consolidation.normal_stress, b.consolidation.normal_stress);
  EXPECT_EQ(a.consolidation.tolerance, b.consolidation.tolerance);
  EXPECT_EQ(a.consolidation.max_unbalanced, b.consolidation.max_unbalanced);
  EXPECT_EQ(a.settings<ShearSpec>().speed, b.settings<ShearSpec>().speed);
  EXPECT_EQ(a.settings<ShearSpec>().final_strain, b.settings<ShearSpec>().final_strain);
  EXPECT_EQ(a.numerics.time_step, b.numerics.time_step);
  EXPECT_EQ(a.numerics.time_step_fraction, b.numerics.time_step_fraction);
  EXPECT_EQ(a.numerics.density_scaling, b.numerics.density_scaling);
  EXPECT_EQ(a.numerics.inertial_number, b.numerics.inertial_number);
  EXPECT_EQ(a.numerics.threads, b.numerics.threads);
  EXPECT_EQ(a.output.folder, b.output.folder);
  EXPECT_EQ(a.output.strain_interval, b.output.strain_interval);
  EXPECT_EQ(a.output.checkpoint_interval, b.output.checkpoint_interval);
  EXPECT_EQ(a.output.snapshot_interval, b.output.snapshot_interval);
  EXPECT_EQ(a.seed, b.seed);
}

// A folder holding a grains.csv (header only), so that grains.scan validates.
inline std::filesystem::path scan_folder_for_config_tests() {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "grainlab-config-test-scan";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "grains.csv") << "id,file,x_m,y_m,z_m,qw,qx,qy,qz,volume_m3,equivalent_diameter_m,border\n";
  return dir;
}

// A spec with a non-default value in every field the config file holds.
inline LabSpec all_fields_changed() {
  LabSpec s;
  s.seed = 987654321987ull;
  s.test = "oedometer";
  s.settings<OedometerSpec>().stresses = {25e3, 1.0 / 3.0 * 1e5, 8e5};
  s.settings<TriaxialSpec>().final_strain = 0.3;
  s.grains.preset = "angular";
  s.grains.folder = "/tmp";
  s.grains.shapes = 7;
  s.grains.faces = 321;
  s.grains.d_min = 0.5e-3 + 1e-19;
  s.grains.d_max = 0.9e-3;
  s.grains.convexity = 0.85;
  s.grains.scan = scan_folder_for_config_tests().string();
  s.grains.scan_border = "keep";
  s.grains.representation = "concave";
  s.material.preset = "ottawa";  // the explicit values below override it
  s.material.law = contact_law<HertzUserLaw>();
  s.material.grain.density = 2500.125;
  s.material.grain.friction = 0.1 + 0.2;  // 0.30000000000000004: needs all 17 digits
  s.material.grain.youngs_modulus = 7.1e10;
  s.material.grain.poisson_ratio = 0.21;
  s.material.grain.restitution = 0.875;
  s.material.grain.k_n = 3.3e11;
  s.material.grain.k_t = 2.2e11;
  s.material.grain.gamma_n = 81;
  s.material.grain.gamma_t = 41.5;
  s.material.wall_friction = 0.05;
  s.box = {0.03, 0.031, 0.016, 1.0 / 3.0 * 1e-3};
  s.specimen = {0.5, "lab", 0.8, 0.55, 0.9, 0.6, 0.7, 0.01, 0.04, 0.1, "runs/first/specimen.bin"};
  s.consolidation = {123456.789, 0.005, 0.02};
  s.settings<ShearSpec>() = {1e-4, 0.2};
  s.numerics = {2e-8, 0.15, 100, 5e-4, 2};
  s.output = {"some \"odd\" folder\\name", 0.002, 300, 0.05};
  return s;
}

}  // namespace grainlab::test
