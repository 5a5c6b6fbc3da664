#include "runtime/shading_data.h"

#include <cmath>
#include <functional>

#include <nlohmann/json.hpp>

#include "runtime/half_float_sections.h"
#include "scene/vertex_pass_rows.h"

namespace weft {

namespace shading_data_section {
std::string table(int id, const char* part) { return "T/" + std::to_string(id) + "/" + part; }
std::string vis(size_t object, const char* part) { return "vis/" + std::to_string(object) + "/" + part; }
std::string mask(size_t object) { return "mask/" + std::to_string(object) + "/bits"; }
}  // namespace shading_data_section

namespace {

using nlohmann::json;

bundle::BundleError bad(const bundle::BundleReader& r, const std::string& section, const std::string& detail) {
  return bundle::BundleError(r.origin(), "section '" + section + "'", section, detail);
}

json parse(const bundle::BundleReader& r, const std::string& section) {
  try {
    return json::parse(r.json(section));
  } catch (const json::exception& e) {
    throw bad(r, section, std::string("not valid JSON: ") + e.what());
  }
}

// An f32 or f16 section (half_float_sections.h) with exactly `count` finite values.
std::vector<float> floats(const bundle::BundleReader& r, const std::string& name, size_t count) {
  std::vector<float> a = read_halves_or_floats(r, name);
  if (a.size() != count)
    throw bad(r, name, "expected " + std::to_string(count) + " values, found " + std::to_string(a.size()));
  for (size_t i = 0; i < a.size(); ++i)
    if (!std::isfinite(a[i])) throw bad(r, name, "non-finite value at " + std::to_string(i));
  return a;
}

using PassRows = std::function<const VertexPassMesh*(size_t object)>;

// The weighting tables of each baked fabric preset.
void read_tables(const bundle::BundleReader& r, ShadingData& out) {
  const std::string TI = shading_data_section::kTablesIndex;
  const json index = parse(r, TI);
  if (!index.is_object()) throw bad(r, TI, "expected an object of fabric presets");
  for (const auto& [preset, j] : index.items()) {
    WeightingTables t;
    std::string u_name, v_name;
    std::vector<int> ranks;
    try {
      const int id = j.at("id").get<int>();
      u_name = shading_data_section::table(id, "u");
      v_name = shading_data_section::table(id, "v");
      // Tables are values at the node grid's directions: on another grid they would be read wrong.
      const std::string grid = j.contains("node_grid") ? j.at("node_grid").get<std::string>() : "equal-area (before 2026-12)";
      if (grid != kNodeGridId)
        throw bad(r, TI, "fabric '" + preset + "': tables baked on node grid '" + grid + "', this build reads '" +
                             kNodeGridId + "': re-bake (weft bake)");
      t.tangent_samples = {j.at("tangent_samples").at(0).get<int>(), j.at("tangent_samples").at(1).get<int>()};
      t.tilts = j.at("tilts").get<std::vector<double>>();
      t.sample_table = j.at("sample_table").get<std::vector<int>>();
      t.xi_grid.n = j.at("xi_resolution").get<int>();
      t.wo_grid.n = j.at("wo_resolution").get<int>();
      t.lambdas = j.at("lambdas").get<std::vector<double>>();
      ranks = j.at("ranks").get<std::vector<int>>();
    } catch (const json::exception& e) {
      throw bad(r, TI, "fabric '" + preset + "': bad field: " + e.what());
    }
    const int samples = t.tangent_samples[0] + t.tangent_samples[1];
    if (t.tangent_samples[0] < 1 || t.tangent_samples[1] < 1 || int(t.tilts.size()) != samples ||
        int(t.sample_table.size()) != samples || t.xi_grid.n < 2 || t.wo_grid.n < 2 || t.lambdas.empty() ||
        ranks.empty() || ranks.size() % t.lambdas.size())
      throw bad(r, TI, "fabric '" + preset + "': inconsistent sizes");
    for (size_t l = 0; l < t.lambdas.size(); ++l)
      if (!(t.lambdas[l] > 0) || (l && !(t.lambdas[l] > t.lambdas[l - 1])))
        throw bad(r, TI, "fabric '" + preset + "': sharpness levels must be positive and increasing");
    const int distinct = int(ranks.size() / t.lambdas.size());
    for (int s : t.sample_table)
      if (s < 0 || s >= distinct) throw bad(r, TI, "fabric '" + preset + "': sample table index out of range");
    size_t nu = 0, nv = 0;
    for (int k : ranks) {
      if (k < 0 || k > 4096) throw bad(r, TI, "fabric '" + preset + "': rank out of range");
      nu += size_t(k) * t.xi_grid.size();
      nv += size_t(k) * t.wo_grid.size();
    }
    const std::vector<float> u = floats(r, u_name, nu), v = floats(r, v_name, nv);
    size_t ou = 0, ov = 0;
    for (int k : ranks) {
      CompressedTable c;
      c.rank = k;
      c.u.assign(u.begin() + ou, u.begin() + ou + size_t(k) * t.xi_grid.size());
      c.v.assign(v.begin() + ov, v.begin() + ov + size_t(k) * t.wo_grid.size());
      ou += c.u.size();
      ov += c.v.size();
      t.tables.push_back(std::move(c));
    }
    out.tables.emplace(preset, std::move(t));
  }
}

// Each occluded object's visibility SDF (PCA), and the κ table it needs.
void read_visibility(const bundle::BundleReader& r, const std::map<size_t, size_t>& vertex_counts,
                     const PassRows& pass_rows, ShadingData& out) {
  const std::string VI = shading_data_section::kVisIndex;
  const json vis = parse(r, VI);
  if (!vis.is_object()) throw bad(r, VI, "expected an object keyed by scene object index");
  for (const auto& [key, j] : vis.items()) {
    ObjectVisibility o;
    size_t object = 0;
    try {
      object = std::stoul(key);
      o.resolution = j.at("resolution").get<int>();
      o.terms = j.at("terms").get<int>();
      o.rms_error = j.value("rms_error", 0.0);
      o.max_error = j.value("max_error", 0.0);
    } catch (const std::exception& e) {
      throw bad(r, VI, "entry '" + key + "': " + e.what());
    }
    if (o.resolution < 2 || o.resolution > 1024 || o.terms < 0 || o.terms > 1024)
      throw bad(r, VI, "entry '" + key + "': resolution or terms out of range");
    const auto vc = vertex_counts.find(object);
    if (vc == vertex_counts.end()) throw bad(r, VI, "entry '" + key + "': no such object in the scene");
    const size_t cells = size_t(o.resolution) * o.resolution;
    o.mean = floats(r, shading_data_section::vis(object, "pca_mean"), cells);
    o.basis = floats(r, shading_data_section::vis(object, "pca_basis"), cells * o.terms);
    if (o.terms == 0) {
      // Every vertex sees the mean (a part whose vertices all see the same sky): no rows carry
      // the vertex count, so one zero term stands in, exact.
      o.terms = 1;
      o.basis.assign(cells, 0.0f);
      o.coefficients.assign(vc->second, 0.0f);
      out.visibility.emplace(object, std::move(o));
      continue;
    }
    const std::string cs = shading_data_section::vis(object, "pca_coeffs");
    const VertexPassMesh* pass = pass_rows(object);
    if (pass && r.array<float>(cs).size() == pass->vertices.size() * size_t(o.terms))  // at the pass vertices
      o.coefficients = blended_rows(*pass, floats(r, cs, pass->vertices.size() * o.terms), size_t(o.terms));
    else
      o.coefficients = floats(r, cs, vc->second * o.terms);
    out.visibility.emplace(object, std::move(o));
  }

  if (r.has(shading_data_section::kKappa)) {
    const std::string K = shading_data_section::kKappa;
    const json kj = parse(r, shading_data_section::kKappaIndex);
    const auto& info = r.section(K);
    if (info.shape.size() != 3) throw bad(r, K, "expected shape [σ_l, σ', β]");
    SigmoidGainTableSpec spec;
    spec.sigma_l_count = int(info.shape[0]);
    spec.sigma_prime_count = int(info.shape[1]);
    spec.beta_count = int(info.shape[2]);
    try {
      spec.sigma_min = kj.at("sigma_min").get<double>();
      spec.sigma_max = kj.at("sigma_max").get<double>();
      out.kappa = SigmoidGainTable::from_gains(spec, floats(r, K, info.element_count()), kj.value("max_fit_error", 0.0));
    } catch (const std::exception& e) {
      throw bad(r, K, e.what());
    }
  }
  if (!out.visibility.empty() && !out.kappa) throw bad(r, shading_data_section::kKappa, "missing: visibility needs κ");
}

// Each occluded cloth object's visibility mask.
void read_masks(const bundle::BundleReader& r, const std::map<size_t, size_t>& vertex_counts, const PassRows& pass_rows,
                ShadingData& out) {
  if (r.has(shading_data_section::kMaskIndex)) {
    const std::string MI = shading_data_section::kMaskIndex;
    const json masks = parse(r, MI);
    if (!masks.is_object()) throw bad(r, MI, "expected an object keyed by scene object index");
    for (const auto& [key, j] : masks.items()) {
      VisibilityMask m;
      size_t object = 0;
      try {
        object = std::stoul(key);
        m.resolution = j.at("resolution").get<int>();
      } catch (const std::exception& e) {
        throw bad(r, MI, "entry '" + key + "': " + e.what());
      }
      if (m.resolution < 8 || m.resolution > 256 || m.resolution % 8)
        throw bad(r, MI, "entry '" + key + "': resolution must be a multiple of 8 within 8..256");
      const auto vc = vertex_counts.find(object);
      if (vc == vertex_counts.end()) throw bad(r, MI, "entry '" + key + "': no such object in the scene");
      const std::string name = shading_data_section::mask(object);
      const auto bits = r.array<std::uint32_t>(name);
      const VertexPassMesh* pass = pass_rows(object);
      const bool at_pass = pass && bits.size() == 2 * pass->vertices.size() * size_t(m.blocks());
      const size_t words = (at_pass ? pass->vertices.size() : vc->second) * size_t(m.blocks());
      if (bits.size() != 2 * words)
        throw bad(r, name, "expected " + std::to_string(2 * words) + " values, found " + std::to_string(bits.size()));
      m.words.resize(words);
      for (size_t i = 0; i < words; ++i) m.words[i] = std::uint64_t(bits[2 * i]) | std::uint64_t(bits[2 * i + 1]) << 32;
      if (at_pass) m.words = heaviest_corner_rows(*pass, m.words, size_t(m.blocks()));
      out.masks.emplace(object, std::move(m));
    }
  }
}

}  // namespace

bool has_shading_data(const bundle::BundleReader& r) { return r.has(shading_data_section::kTablesIndex); }

ShadingData read_shading_data(const bundle::BundleReader& r, const std::map<size_t, size_t>& vertex_counts) {
  return read_shading_data(r, vertex_counts, {});
}

ShadingContents read_shading_contents(const bundle::BundleReader& r) {
  ShadingContents c;
  c.tables = has_shading_data(r);
  auto keys = [&](const char* index, std::set<size_t>& out) {
    if (!r.has(index)) return;
    const json j = parse(r, index);
    if (!j.is_object()) throw bad(r, index, "expected an object keyed by scene object index");
    for (const auto& item : j.items()) {
      const std::string& key = item.key();
      size_t used = 0;
      size_t object = 0;
      try {
        object = std::stoul(key, &used);
      } catch (const std::exception&) {
      }
      if (used == 0 || used != key.size()) throw bad(r, index, "entry '" + key + "': not a scene object index");
      out.insert(object);
    }
  };
  keys(shading_data_section::kVisIndex, c.visibility);
  keys(shading_data_section::kMaskIndex, c.masks);
  return c;
}

ShadingData read_scene_shading_data(const bundle::BundleReader& r, const Scene& scene, ShadingParts parts) {
  std::map<size_t, size_t> counts;
  std::map<size_t, const VertexPassMesh*> passes;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const TriangleMesh& m = scene.objects[i].mesh;
    counts[i] = m.positions.size();
    if (!pass_of(m).whole()) passes[i] = &pass_of(m);
  }
  return read_shading_data(r, counts, passes, parts);
}

ShadingData read_shading_data(const bundle::BundleReader& r, const std::map<size_t, size_t>& vertex_counts,
                              const std::map<size_t, const VertexPassMesh*>& passes, ShadingParts parts) {
  // Rows stored at an object's pass vertices only: how many, where it has a pass subset.
  auto pass_rows = [&](size_t object) -> const VertexPassMesh* {
    const auto p = passes.find(object);
    return p == passes.end() ? nullptr : p->second;
  };
  ShadingData out;
  if (parts.tables) read_tables(r, out);
  if (parts.visibility) read_visibility(r, vertex_counts, pass_rows, out);
  if (parts.masks) read_masks(r, vertex_counts, pass_rows, out);
  return out;
}

}  // namespace weft
