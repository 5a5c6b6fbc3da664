#pragma once
// Seed 000's baked data in a bundle (BUNDLE_FORMAT.md, "Seed 000 sections"): the weighting
// tables T of each baked fabric (SVD factors), the per-vertex visibility SDF of each occluded
// object (cloth, floor, occluder) as PCA (mean, basis, coefficients), and the sigmoid gain table κ. Written by
// `weft bake` beside the scene sections, read by `weft run` / `weft render --method iwasaki`.
#include <map>
#include <optional>
#include <string>

#include <vector>

#include "bake/sigmoid_gain.h"
#include "bake/weighting_tables.h"
#include "bundle/bundle_reader.h"
#include "bundle/bundle_writer.h"

namespace weft {

namespace iwasaki_section {
inline constexpr const char* kTablesIndex = "bake/T";     // json: {preset: {id, grids, levels, samples, ranks}}
inline constexpr const char* kVisIndex = "bake/vis";      // json: {object index: {resolution, terms, errors}}
inline constexpr const char* kKappa = "kappa";            // f32 [σ_l, σ', β]: normalised gains κ·s
inline constexpr const char* kKappaIndex = "bake/kappa";  // json: the table's spec and fit error
std::string table(int id, const char* part);              // "T/<id>/u", "T/<id>/v" (f32, all levels concatenated)
std::string vis(size_t object, const char* part);         // "vis/<i>/pca_mean" [cells], "pca_basis" [terms, cells],
                                                          // "pca_coeffs" [vertices, terms]
}  // namespace iwasaki_section

// One object's visibility: d_v = mean + basis · c_v on a resolution² grid over (θ, φ) of
// the vertex's thread-1 frame (render/bake/visibility.md).
struct ObjectVisibility {
  int resolution = 0;                // cells = resolution², row-major [θ][φ]
  int terms = 0;
  std::vector<float> mean;           // [cells]
  std::vector<float> basis;          // [terms][cells]
  std::vector<float> coefficients;   // [vertices][terms]
  size_t vertex_count() const { return terms ? coefficients.size() / terms : 0; }
  double rms_error = 0, max_error = 0;  // of the PCA reconstruction (radians)
};

struct IwasakiBundleData {
  std::map<std::string, WeightingTables> tables;     // by fabric preset
  std::map<size_t, ObjectVisibility> visibility;     // by scene object index; absent: unoccluded
  std::optional<SigmoidGainTable> kappa;             // present whenever visibility is
};

// Adds the sections.
void add_iwasaki_sections(bundle::BundleWriter& writer, const IwasakiBundleData& data);

// True when the bundle holds seed 000 tables (the `bake/T` index).
bool has_iwasaki_sections(const bundle::BundleReader& reader);

// Reads them back. Throws bundle::BundleError naming the section when one is missing, has the
// wrong type or shape, or holds invalid values; `vertex_counts[i]` (object i's vertices) checks
// the coefficients.
IwasakiBundleData read_iwasaki_sections(const bundle::BundleReader& reader, const std::map<size_t, size_t>& vertex_counts);

}  // namespace weft
