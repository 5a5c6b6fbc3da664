#pragma once
// The baked weighting-table data of a bundle (BUNDLE_FORMAT.md, "Weighting-table sections"): the weighting
// tables T of each baked fabric (SVD factors), the per-vertex visibility SDF of each occluded
// object (cloth, floor, occluder) as PCA (mean, basis, coefficients), the sigmoid gain table κ,
// and each occluded cloth object's per-vertex visibility mask (runtime/visibility_mask.h). Written by
// `weft bake` beside the scene sections (render/bake/writers/shading_data_writer.h), read here for
// `weft run` and `weft render`. Method-neutral: the iwasaki, mizutani and sheer rungs read the
// tables, the per-vertex rungs and the weave layer the visibility and masks, the floors the
// visibility; what each rung needs is declared in its RuntimeMethod (weighting_tables, masks).
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "bundle/bundle_reader.h"
#include "runtime/object_visibility.h"
#include "runtime/sigmoid_gain_table.h"
#include "runtime/visibility_mask.h"
#include "runtime/weighting_tables.h"
#include "scene/scene.h"
#include "scene/vertex_pass_mesh.h"

namespace weft {

namespace shading_data_section {
inline constexpr const char* kTablesIndex = "bake/T";     // json: {preset: {id, grids, levels, samples, ranks}}
inline constexpr const char* kVisIndex = "bake/vis";      // json: {object index: {resolution, terms, errors}}
inline constexpr const char* kKappa = "kappa";            // f32 [σ_l, σ', β]: normalised gains κ·s
inline constexpr const char* kKappaIndex = "bake/kappa";  // json: the table's spec and fit error
inline constexpr const char* kMaskIndex = "bake/mask";    // json: {object index: {resolution}}; optional
std::string mask(size_t object);                          // "mask/<i>/bits" (u32 [vertices, blocks, 2]: low, high word)
std::string table(int id, const char* part);              // "T/<id>/u", "T/<id>/v" (f32, all levels concatenated)
std::string vis(size_t object, const char* part);         // "vis/<i>/pca_mean" [cells], "pca_basis" [terms, cells],
                                                          // "pca_coeffs" [vertices, terms]
}  // namespace shading_data_section

struct ShadingData {
  std::map<std::string, WeightingTables> tables;     // by fabric preset
  std::map<size_t, ObjectVisibility> visibility;     // by scene object index; absent: unoccluded
  std::optional<SigmoidGainTable> kappa;             // present whenever visibility is
  std::map<size_t, VisibilityMask> masks;            // cloth objects' bit masks (iwasaki_vertex_mask); absent: unoccluded
};

// The parts of a bundle's shading data a reader loads. Each runtime method declares the parts it
// reads (RuntimeMethod::bake_reads); the kiosk loads only those of the method it draws with.
struct ShadingParts {
  bool tables = true;      // the weighting tables (bake/T, T/<id>/*)
  bool visibility = true;  // the per-vertex visibility SDF (bake/vis, vis/<i>/*) and κ
  bool masks = true;       // the visibility masks (bake/mask, mask/<i>/bits)
  static constexpr ShadingParts none() { return {false, false, false}; }
  bool any() const { return tables || visibility || masks; }
  ShadingParts operator|(const ShadingParts& o) const {
    return {tables || o.tables, visibility || o.visibility, masks || o.masks};
  }
  bool operator==(const ShadingParts&) const = default;
};

// What a bundle's bake holds, from its index sections alone (no payload read): enough to choose a
// method before loading the parts it reads.
struct ShadingContents {
  bool tables = false;            // the bake/T index: the bundle was baked with its shading data
  std::set<size_t> visibility;    // objects with baked visibility (occluded)
  std::set<size_t> masks;         // objects with a visibility mask
};

// True when the bundle holds weighting tables (the `bake/T` index).
bool has_shading_data(const bundle::BundleReader& reader);

// The indices of the bundle's shading data. Throws bundle::BundleError naming an index that is not
// an object keyed by scene object index.
ShadingContents read_shading_contents(const bundle::BundleReader& reader);

// Reads them back. Throws bundle::BundleError naming the section when one is missing, has the
// wrong type or shape, or holds invalid values; `vertex_counts[i]` (object i's vertices) checks
// the coefficients.
ShadingData read_shading_data(const bundle::BundleReader& reader, const std::map<size_t, size_t>& vertex_counts);
// The same where an object may carry a pass subset (scene/vertex_pass_mesh.h): its per-vertex rows
// (PCA coefficients, mask bits) may then be stored at the pass vertices only, and are spread back
// to every vertex (coefficients blended, bits of the heaviest corner), as the bake made them.
// `parts` leaves out what nobody will read (a part left out stays empty).
ShadingData read_shading_data(const bundle::BundleReader& reader, const std::map<size_t, size_t>& vertex_counts,
                              const std::map<size_t, const VertexPassMesh*>& passes, ShadingParts parts = {});
// The scene's objects' vertex counts and pass subsets (the scene as read from the same bundle).
ShadingData read_scene_shading_data(const bundle::BundleReader& reader, const Scene& scene, ShadingParts parts = {});

}  // namespace weft
