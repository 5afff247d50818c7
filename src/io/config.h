// The run configuration file: TOML in, LabSpec out, and back.
//
// Layout: top-level `test` and `seed`, then tables [grains], [material],
// [box], [specimen], [consolidation], each registered lab test's own table
// ([shear], [oedometer], [triaxial]: lab/lab_registry.h), [numerics],
// [output], whose keys are the field names of lab/lab_spec.h and of the
// tests' settings (material.contact_law is MaterialSpec::law; the other
// material keys are those of Material).
// A contact law's parameters (its parameter list, dynamics/law_parameters.h)
// are read from its own table [material.<law>] or as flat [material] keys.
// `material.preset` applies a sand preset (lab/sand_presets.h) first; every
// other key in the file then overrides it. Every problem is an InputError
// naming the file, the line, the dotted key, what is wrong and what to do.
#pragma once

#include "lab/lab_spec.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace grainlab {

// Reads and parses a config file (missing or unreadable file: InputError).
LabSpec load_config(const std::filesystem::path& file);

// Parses config text; source_name (a file name) is used in messages.
LabSpec parse_config(std::string_view toml_text, const std::string& source_name);

// Throws InputError naming source_name and the dotted key of the first impossible value.
void validate(const LabSpec& spec, const std::string& source_name);

// A complete config for lab test `test` (lab/lab_registry.cpp) and contact law
// `law` with every key they read, its unit and meaning in a comment, and the
// struct defaults (the law's parameters in its table [material.<law>]).
std::string default_config_toml(const std::string& test = LabSpec{}.test, ContactLaw law = {});

// Every key of `spec` as TOML, exact (shortest round-trip doubles); parse_config reads it back equal.
std::string to_toml(const LabSpec& spec);

// Dotted keys whose values differ between a and b (empty: same config).
std::vector<std::string> config_differences(const LabSpec& a, const LabSpec& b);

}  // namespace grainlab
