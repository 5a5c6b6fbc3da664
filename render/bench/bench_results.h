#pragma once
// What one `weft bench` run measured, as its report and CSVs print it.
#include <string>

#include "bench/number_text.h"
#include <vector>

#include "bench/ladder.h"
#include "bench/reference_set.h"
#include "bench/stability.h"

namespace weft::bench {

// One method on one case: speed at the speed size, accuracy at the accuracy size.
struct Row {
  std::string scene, fabric, env, method;
  double ms = 0.0;
  int frames = 0;
  double rmse = -1.0;  // < 0: not measured
  size_t cloth_pixels = 0;
  size_t bundle_bytes = 0;  // iwasaki rows: weighting tables + visibility PCA in the bundle
  std::string tables;       // iwasaki rows: what the tables hold
  std::string note, image, error_image, reference_image;
  // Thin-occluder scene only (< 0: not measured): masked_error in the sun's shadow and in the
  // sunlit band beside it.
  double shadow_rmse = -1.0, shadow_ratio = -1.0, band_ratio = -1.0;
  size_t shadow_pixels = 0, band_pixels = 0;
  bool visibility = false;  // the method shades with scene visibility (the baked SDF)
  // Floor and occluders (Lambertian pixels, < 0: none in view): masked_error there.
  double lambert_rmse = -1.0, lambert_ratio = -1.0;
  int sg_count = 0;               // SGs the frame was lit by
  std::string setting;            // target-error rows: the chosen setting in words (describe())
  int subdivision = -1;           // target-error and subdivided rows: the cloth meshes' levels (< 0: not refined)
  size_t cloth_mesh_bytes = 0;    // the cloth meshes' bundle sections (scene_bundle_writer.h)
  double visibility_bake_s = -1;  // subdivided rows: the visibility bake on the refined cloth (< 0: none)
  int reference_tangent_samples = 0;  // N_j of the reference the row is measured against
};

// One point of the SG-count sweep.
struct SweepRow {
  std::string method;
  int sg_count = 0;
  double ms = 0.0, rmse = 0.0;
};

// One point of a bake-knob sweep.
struct KnobRow {
  std::string value;
  double ms = 0.0, rmse = 0.0, bake_s = 0.0;
  size_t table_bytes = 0, visibility_bytes = 0;
  std::string tables;  // what the tables hold (tables_summary)
};
struct KnobSweep {
  std::string knob, file, default_value;
  std::vector<KnobRow> rows;
  std::string skipped;  // why nothing was measured
};

// One method × stress case of the stability table.
struct StabilityCell {
  std::string method, stress, notes;
  StressResult r;
};

// The method column of a weighting-table method's target-error row: "iwasaki_vertex (target 0.1)".
inline std::string target_label(const std::string& method, double target) {
  return method + " (target " + fmt(target) + ")";
}

struct BenchResults {
  std::vector<std::string> missing;  // the ladder's methods this build's runtime lacks
  bool run_iwasaki = false;          // iwasaki is among the measured methods
  std::string target_label;          // iwasaki's target-error rows' method label
  std::vector<Row> rows;
  std::string renderer;              // GL_RENDERER of the rows' frames
  std::string thin_occluder_case;    // what the thin-occluder table's text says of its case
  std::vector<SweepRow> sweep;
  std::string sweep_case;
  std::vector<KnobSweep> knob_sweeps;
  std::string knob_case;
  KnobRow knob_default;              // the paper-default bundle on the knob sweeps' case
  int paper_sdf_resolution = 0;      // the paper-default bundle's SDF resolution
  std::vector<StabilityCell> stability;
  double seconds = 0.0;              // the whole run, before writing the outputs
  double reference_seconds = 0.0;
  int references_rendered = 0, references_cached = 0;
  std::vector<ReferenceRecord> references;  // each reference's N_j and how it was chosen
};

}  // namespace weft::bench
