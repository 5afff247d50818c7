// `grainlab ct`: X-ray CT volumes to grain meshes (segment), and a synthetic
// scan to try it on (synth).
#include "apps/commands.h"
#include "core/error.h"
#include "core/timer.h"
#include "ct/image_io.h"
#include "ct/segmentation.h"
#include "ct/segmentation_files.h"
#include "ct/synthetic_volume.h"
#include "geometry/mesh_io.h"

#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace grainlab::apps {

namespace {

namespace fs = std::filesystem;

struct SegmentArgs {
  std::string image, out, type, format = "stl";
  std::vector<std::int64_t> size, crop;
  int bin = 1;
  std::optional<double> voxel_size;
  std::optional<float> threshold;
  bool labels = false, force = false, quiet = false;
  ct::SegmentOptions options;
};

struct SynthArgs {
  std::string out, truth, type = "uint16";
  ct::SyntheticSpec spec;
};

int run_segment(const SegmentArgs& a) {
  Stopwatch clock;
  ct::SegmentOptions options = a.options;
  options.threshold = a.threshold;
  ct::validate(options);
  if (a.labels && a.threshold) input_error("--threshold does not apply to a label image (--labels)");
  ct::ImageSource source{a.image, std::nullopt, a.voxel_size, {}};
  if (!a.crop.empty()) source.window.crop = ct::parse_crop(a.crop);
  source.window.bin = a.bin;
  if (!a.size.empty() || !a.type.empty()) {
    if (a.size.size() != 3 || a.type.empty()) {
      input_error("a raw image needs both --size NX NY NZ and --type uint8|uint16|float32");
    }
    source.raw = ct::RawLayout{{a.size[0], a.size[1], a.size[2]}, ct::parse_voxel_type(a.type)};
  }
  ct::check_output_folder(a.out, a.force);

  const ct::ImageHeader h = ct::read_image_header(source);
  ct::check_memory(h.size, a.image, h.read_buffer_bytes);
  if (!a.quiet) {
    fmt::print(stderr, "ct: {} ({}): {} x {} x {} voxels of {:.4g} x {:.4g} x {:.4g} um (from {})\n", a.image, h.format,
               h.stored_size[0], h.stored_size[1], h.stored_size[2], h.spacing[0] / a.bin * 1e6,
               h.spacing[1] / a.bin * 1e6, h.spacing[2] / a.bin * 1e6, h.spacing_source);
    if (h.size != h.stored_size) {
      fmt::print(stderr, "ct: reading {} x {} x {} voxels of {:.4g} um ({}{})\n", h.size[0], h.size[1], h.size[2],
                 h.spacing[0] * 1e6, a.crop.empty() ? "" : "--crop", a.bin > 1 ? fmt::format("{}--bin {}", a.crop.empty() ? "" : ", ", a.bin) : "");
    }
  }
  ct::Progress progress(!a.quiet);
  ct::Segmentation s;
  if (a.labels) {
    s = ct::segment_labels(ct::read_label_volume(source), options, progress);
  } else {
    const ct::GreyVolume grey = ct::read_grey_volume(source);
    s = ct::segment_grey(grey, options, progress);
    if (!a.quiet) fmt::print(stderr,
               "ct: threshold {:.6g} ({}; pore mean {:.6g}, grain mean {:.6g}), solid fraction {:.3f}, {} pore voxels "
               "filled; watershed depth h {:.2f} voxels ({})\n",
               s.threshold, s.otsu ? "Otsu" : "--threshold", s.pore_level, s.solid_level, s.solid_fraction,
               s.filled_voxels, s.h,
               options.h == 0 ? fmt::format("a fifth of the median inscribed radius, {:.1f} voxels", s.typical_radius)
                              : std::string("--h"));
    if (!a.quiet && options.merge_ratio > 0) {
      fmt::print(stderr, "ct: split with hills {} voxel deep, {} regions merged back (--merge-ratio {})\n",
                 ct::kOverSplitDepth, s.merged_regions, options.merge_ratio);
    }
  }
  ct::write_segmentation(s, a.out, a.force, a.format);
  int border = 0, over_budget = 0, pieces = 0, merges = 0, splits = 0;
  for (const auto& g : s.grains) {
    border += g.border;
    over_budget += !g.within_budget;
    pieces += g.dropped_pieces;
    merges += g.quality.likely_merge;
    splits += g.quality.likely_split;
  }
  fmt::print("wrote {} grains ({} touching the image border) to {} in {:.1f} s; {} regions under --min-voxels {} "
             "dropped\n",
             s.grains.size(), border, a.out, clock.seconds(), s.dropped_regions, options.min_voxels);
  if (over_budget) fmt::print("  {} grains kept more than --faces {} faces to stay closed\n", over_budget, options.meshing.faces);
  if (pieces) fmt::print("  {} small separate surface pieces left out (loose fragments of a label)\n", pieces);
  if (merges + splits == 0) {
    fmt::print("  grain_quality.csv: no grain flagged as likely merged or split (distance maxima with h {:.2f} voxels, "
               "convexity, contacts)\n",
               s.quality_h);
  } else {
    fmt::print("  grain_quality.csv: {} grains flagged as likely merged, {} as likely split (distance maxima with h "
               "{:.2f} voxels, convexity, contacts): look at them, and tune --h\n",
               merges, splits, s.quality_h);
  }
  fmt::print("  measure them with `grainlab grains stats {}`\n", a.out);
  return 0;
}

int run_synth(const SynthArgs& a) {
  Stopwatch clock;
  const ct::VoxelType type = ct::parse_voxel_type(a.type);
  ct::SyntheticSpec spec = a.spec;
  if (type == ct::VoxelType::UInt8) {
    spec.pore_level = 50;
    spec.solid_level = 200;
  }
  const ct::SyntheticScene scene = ct::make_synthetic_scene(spec);
  const std::string ext = fs::path(a.out).extension().string();
  const bool slices = ext.empty() || a.out.back() == '/';
  if (ext == ".tif" || ext == ".tiff" || ext == ".raw" || slices) {
    fmt::print(stderr, "ct: note: {} hold no voxel size: segment with --voxel-size {:g}{}\n",
               slices ? "slice folders" : ext + " files", a.spec.voxel_size,
               ext == ".raw" ? fmt::format(" --size {0} {0} {0} --type {1}", a.spec.size, a.type) : "");
  }
  if (slices) {
    std::error_code ec;
    if (fs::exists(a.out, ec) && !fs::is_empty(a.out, ec)) {
      input_error("--out '{}' is a folder that is not empty: give a new folder for the slices", a.out);
    }
    ct::write_grey_slices(scene.volume, a.out, "slice_", ".tif", type);
  } else {
    ct::write_grey_volume(scene.volume, a.out, type);
  }
  if (!a.truth.empty()) {
    std::error_code ec;
    fs::create_directories(a.truth, ec);
    if (ec) input_error("cannot create --truth folder '{}': {}", a.truth, ec.message());
    for (std::size_t g = 0; g < scene.grains.size(); ++g) {
      write_stl(scene.grains[g].mesh, fs::path(a.truth) / fmt::format("true_{:04d}_{}.stl", g + 1,
                                                                        scene.grains[g].kind));
    }
  }
  fmt::print("wrote a {0}^3 synthetic scan of {1} grains ({2} touching pairs; {3:g} um voxels, blur {4:g} voxel, "
             "noise {5:g}) to {6} in {7:.1f} s{8}\n",
             a.spec.size, scene.grains.size(), scene.touching.size(), a.spec.voxel_size * 1e6, a.spec.blur,
             a.spec.noise, a.out, clock.seconds(),
             a.truth.empty() ? "" : fmt::format("; true meshes in {}", a.truth));
  return 0;
}

}  // namespace

Command add_ct_command(CLI::App& app) {
  auto seg = std::make_shared<SegmentArgs>();
  auto syn = std::make_shared<SynthArgs>();
  auto* ct = app.add_subcommand("ct", "X-ray CT scans to grain meshes (segment), and a synthetic scan to try it (synth)");
  ct->require_subcommand(1);

  auto* s = ct->add_subcommand(
      "segment",
      "cut a 3D X-ray CT image of sand into grains and write one closed mesh per grain (metres) and grains.csv.\n"
      "Steps:\n"
      "  1. threshold: voxels brighter than T are solid; T is Otsu's (the grey level that best separates the\n"
      "     pore and grain peaks of the histogram) unless --threshold gives it;\n"
      "  2. clean: enclosed pores of fewer than --min-voxels voxels (noise) become solid;\n"
      "  3. split touching grains: the distance from each solid voxel to the nearest pore has one hill per grain\n"
      "     and a saddle at each contact; hills rising less than --h voxels above their saddle are merged\n"
      "     (h-maxima), the rest seed a watershed that cuts the solid at the necks;\n"
      "  4. drop regions of fewer than --min-voxels voxels;\n"
      "  5. mesh each grain: iso-surface at T of its grey levels (sub-voxel, from the partial volume of surface\n"
      "     voxels; halfway to a touching neighbour), Taubin smoothing (--smooth), simplification to --faces,\n"
      "     and the mesh check grainlab applies to any grain;\n"
      "  6. measure each mesh: centroid, principal frame, volume, equivalent diameter.\n"
      "grains.csv columns: id, file, x_m, y_m, z_m (centroid, image world coordinates, m), qw, qx, qy, qz (the\n"
      "rotation taking x, y, z onto the long, intermediate and short principal axes), volume_m3,\n"
      "equivalent_diameter_m (sphere of equal volume) and border (1: the grain touches a face of the image\n"
      "and is cut off).\n"
      "grain_quality.csv, to find the grains the watershed got wrong: id, voxels, volume_m3,\n"
      "equivalent_diameter_m, convexity (volume / convex hull volume), distance_maxima (hills of the grain's own\n"
      "distance map rising more than h), contacts and contact_area_m2 (voxel faces shared with other grains x\n"
      "face area), largest_contact_ratio (largest contact / cross-section pi r^2 of the smaller grain), and\n"
      "likely_merge (2+ maxima, or convexity < 0.85) and likely_split (ratio > 0.5) flags.\n"
      "Formats: multi-page TIFF, NRRD (.nrrd, .nhdr), MetaImage (.mha, .mhd), headerless raw (--size, --type),\n"
      "and a folder of 2D TIFF (8/16-bit, float) or PNG slices, one per z, ordered by the number in their names\n"
      "(slice_9 before slice_10), with no gap, all of one size and pixel type.\n"
      "Units: NRRD spacing and origin are in the header's 'space units' (or 'units': m, mm, um, microns, ...),\n"
      "millimetres when it names none; MetaImage is read as millimetres (the ITK convention). TIFF, raw files and\n"
      "slice folders have no voxel size: give --voxel-size in metres (it also overrides a file's). A voxel size\n"
      "outside 0.1 um - 1 mm is refused as a unit mistake.\n"
      "Large scans: --crop and --bin read only a box, or 2x2x2 averages; slice folders and raw files are read a\n"
      "slice at a time, and a volume that would not fit in memory (40 bytes per voxel read) is refused.\n"
      "Example: grainlab ct synth --out scan.nrrd && grainlab ct segment scan.nrrd --out grains/");
  s->add_option("image", seg->image, "the 3D image file, or a folder of 2D slices")->required();
  s->add_option("--out", seg->out, "output folder (created; must be empty unless --force)")->required();
  s->add_option("--voxel-size", seg->voxel_size, "voxel edge length in metres (e.g. 25e-6); wins over the file's");
  s->add_option("--size", seg->size, "raw files: voxels along x, y, z")->expected(3);
  s->add_option("--type", seg->type, "raw files: voxel type, little endian")
      ->check(CLI::IsMember({"uint8", "uint16", "float32"}));
  s->add_option("--crop", seg->crop,
                "x0,y0,z0,x1,y1,z1: read only voxels x0 <= x < x1, y0 <= y < y1, z0 <= z < z1 (voxel indices from 0, "
                "before --bin)")
      ->expected(6)
      ->delimiter(',');
  s->add_option("--bin", seg->bin,
                "average b x b x b voxels into one while reading (2: 8x fewer voxels, voxels twice as large; a "
                "remainder of fewer than b voxels is left out)")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  s->add_flag("--labels", seg->labels, "the image is already segmented: 0 = pore, 1, 2, ... = grains (steps 4-6 only)");
  s->add_option("--threshold", seg->threshold, "grey level above which a voxel is solid (default: Otsu's)");
  s->add_option("--h", seg->options.h,
                "h-maxima depth in voxels: touching grains are split when each one's inscribed radius exceeds the "
                "contact neck's by more than h; larger h merges more (dented grains stay whole), smaller splits more. "
                "0: a fifth of the grains' median inscribed radius (at least 1 voxel), which suits 14 to 72 voxels "
                "across; give it for a wide grading (small grains against large ones) and check grains.csv. With the merge "
                "step (--merge-ratio above 0, the default) the markers are 0.5 voxel deep and h serves only the quality "
                "table's distance maxima")
      ->capture_default_str();
  s->add_option("--merge-ratio", seg->options.merge_ratio,
                "split with hills 0.5 voxel deep, then merge two touching regions back into one grain when the "
                "thickest ball through their shared boundary has at least this fraction of the smaller region's "
                "inscribed radius (a cut through one grain; a contact between grains is a much thinner neck). "
                "Finds touching elongated grains that h-maxima alone merges. 0: h-maxima at depth --h alone")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  s->add_option("--threads", seg->options.threads, "worker threads meshing the grains (0 = all cores)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  s->add_option("--min-voxels", seg->options.min_voxels,
                "smallest grain kept, in voxels (smaller regions are noise or fragments; smaller enclosed pores are "
                "filled)")
      ->capture_default_str();
  s->add_option("--faces", seg->options.meshing.faces, "triangles per grain mesh (the paper's scans: 2000)")
      ->capture_default_str();
  s->add_option("--smooth", seg->options.meshing.smooth_iterations,
                "Taubin smoothing passes on each surface before simplification (0: none)")
      ->capture_default_str();
  s->add_option("--format", seg->format, "mesh file format")->check(CLI::IsMember({"stl", "obj"}))->capture_default_str();
  s->add_flag("--force", seg->force, "replace the grain meshes, grains.csv and grain_quality.csv of a non-empty --out folder");
  s->add_flag("--quiet", seg->quiet, "no progress or information lines on standard error (errors still go there)");

  auto* y = ct->add_subcommand(
      "synth",
      "write a synthetic X-ray CT scan of known grains to try `ct segment` on: ellipsoids, rounded and sub-angular\n"
      "grains and dented (concave) grains from `grains generate`, at random positions and orientations, some pairs\n"
      "touching, voxelized with partial volume (4x4 sample lines per voxel), blurred (Gaussian, --blur voxels) and\n"
      "with Gaussian noise (--noise, a fraction of the grain-pore contrast). Pores are grey 10000, grains 40000 (50 and 200 for uint8).\n"
      "Example: grainlab ct synth --out scan.nrrd --truth truth/ && grainlab ct segment scan.nrrd --out grains/");
  y->add_option("--out", syn->out,
                "image file: .nrrd, .mha (voxel size stored, in mm), .tif or .raw; or a folder (no extension, or a "
                "trailing /) for one 2D TIFF per slice, slice_0000.tif ...")
      ->required();
  y->add_option("--truth", syn->truth, "folder for the true grain meshes (STL, metres)");
  y->add_option("--size", syn->spec.size, "voxels along each side")->capture_default_str();
  y->add_option("--grains", syn->spec.grains, "number of grains")->capture_default_str();
  y->add_option("--touching", syn->spec.touching_pairs, "pairs of grains placed touching")->capture_default_str();
  y->add_option("--grain-size", syn->spec.grain_size, "mean intermediate grain dimension in voxels (+-15 %)")
      ->capture_default_str();
  y->add_option("--voxel-size", syn->spec.voxel_size, "voxel edge length (m)")->capture_default_str();
  y->add_option("--blur", syn->spec.blur, "Gaussian blur, standard deviation in voxels")->capture_default_str();
  y->add_option("--noise", syn->spec.noise, "noise standard deviation / (grain - pore grey level)")
      ->capture_default_str();
  y->add_option("--seed", syn->spec.seed, "random seed (same seed, same scan)")->capture_default_str();
  y->add_option("--type", syn->type, "voxel type written")
      ->check(CLI::IsMember({"uint8", "uint16", "float32"}))
      ->capture_default_str();

  return [ct, s, y, seg, syn]() {
    if (!*ct) return -1;
    if (*s) return run_segment(*seg);
    if (*y) return run_synth(*syn);
    return -1;
  };
}

}  // namespace grainlab::apps
