#include "bake/writers/shading_data_writer.h"

#include "runtime/half_float_sections.h"
#include "scene/vertex_pass_rows.h"

#include <nlohmann/json.hpp>

namespace weft {

using nlohmann::json;

void add_shading_data_sections(bundle::BundleWriter& w, const ShadingData& d, const Scene* scene) {
  // The object's pass subset, where its rows are stored at the pass vertices only.
  auto subset = [&](size_t object, size_t vertices) -> const VertexPassMesh* {
    if (!scene || object >= scene->objects.size()) return nullptr;
    const VertexPassMesh& p = pass_of(scene->objects[object].mesh);
    return !p.whole() && p.corners.size() == vertices ? &p : nullptr;
  };
  json index = json::object();
  int id = 0;
  for (const auto& [preset, t] : d.tables) {
    json ranks = json::array(), errors = json::array();
    std::vector<float> u, v;
    for (const CompressedTable& c : t.tables) {
      ranks.push_back(c.rank);
      errors.push_back(c.error);
      u.insert(u.end(), c.u.begin(), c.u.end());
      v.insert(v.end(), c.v.begin(), c.v.end());
    }
    index[preset] = {{"id", id},
                     {"tangent_samples", {t.tangent_samples[0], t.tangent_samples[1]}},
                     {"tilts", t.tilts},
                     {"sample_table", t.sample_table},
                     {"node_grid", kNodeGridId},
                     {"xi_resolution", t.xi_grid.n},
                     {"wo_resolution", t.wo_grid.n},
                     {"lambdas", t.lambdas},
                     {"ranks", ranks},
                     {"svd_errors", errors}};
    add_halves_or_floats(w, shading_data_section::table(id, "u"), u, {u.size()});
    add_halves_or_floats(w, shading_data_section::table(id, "v"), v, {v.size()});
    ++id;
  }
  w.add_json(shading_data_section::kTablesIndex, index.dump());
  json vis = json::object();
  for (const auto& [object, o] : d.visibility) {
    const uint64_t cells = uint64_t(o.resolution) * o.resolution;
    vis[std::to_string(object)] = {{"resolution", o.resolution}, {"terms", o.terms},
                                   {"rms_error", o.rms_error}, {"max_error", o.max_error}};
    w.add_array<float>(shading_data_section::vis(object, "pca_mean"), o.mean, {cells});
    add_halves_or_floats(w, shading_data_section::vis(object, "pca_basis"), o.basis, {uint64_t(o.terms), cells});
    if (const VertexPassMesh* p = subset(object, o.vertex_count()))
      w.add_array<float>(shading_data_section::vis(object, "pca_coeffs"), pass_vertex_rows(*p, o.coefficients, size_t(o.terms)),
                         {uint64_t(p->vertices.size()), uint64_t(o.terms)});
    else
      w.add_array<float>(shading_data_section::vis(object, "pca_coeffs"), o.coefficients,
                         {uint64_t(o.vertex_count()), uint64_t(o.terms)});
  }
  w.add_json(shading_data_section::kVisIndex, vis.dump());
  if (d.kappa) {
    const SigmoidGainTableSpec& s = d.kappa->spec();
    w.add_array<float>(shading_data_section::kKappa, d.kappa->normalized_gains(),
                       {uint64_t(s.sigma_l_count), uint64_t(s.sigma_prime_count), uint64_t(s.beta_count)});
    w.add_json(shading_data_section::kKappaIndex,
               json{{"sigma_min", s.sigma_min}, {"sigma_max", s.sigma_max}, {"max_fit_error", d.kappa->max_fit_error()}}
                   .dump());
  }
  if (!d.masks.empty()) {
    json masks = json::object();
    for (const auto& [object, m] : d.masks) {
      masks[std::to_string(object)] = {{"resolution", m.resolution}};
      const VertexPassMesh* p = subset(object, m.vertex_count());
      const std::vector<std::uint64_t> words = p ? pass_vertex_rows(*p, m.words, size_t(m.blocks())) : m.words;
      std::vector<std::uint32_t> bits;
      bits.reserve(2 * words.size());
      for (const std::uint64_t word : words) bits.insert(bits.end(), {std::uint32_t(word), std::uint32_t(word >> 32)});
      w.add_array<std::uint32_t>(shading_data_section::mask(object), bits,
                                 {uint64_t(words.size() / size_t(m.blocks())), uint64_t(m.blocks()), 2});
    }
    w.add_json(shading_data_section::kMaskIndex, masks.dump());
  }
}

}  // namespace weft
