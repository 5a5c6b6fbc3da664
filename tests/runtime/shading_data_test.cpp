// The weighting-table sections of a bundle (render/bake/writers/shading_data_writer.h): what add_shading_data_sections writes
// reads back bit for bit, and a bundle with a section missing or of the wrong size is refused
// with a BundleError naming that section (visibility masks included).
#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include <random>

#include "bake/writers/shading_data_writer.h"
#include "bake/tables/weighting_bake.h"
#include "core/fabric.h"

using namespace weft;

namespace {

ShadingData sample_data() {
  ShadingData d;
  BakeSettings s;
  s.tangent_samples = {2, 1};
  s.xi_resolution = s.wo_resolution = s.wi_resolution = 8;
  s.lambda_levels = 2;
  d.tables.emplace("linen_plain", bake_weighting_tables(load_fabric_preset("linen_plain", WEFT_SOURCE_ASSETS "/fabrics"), s));
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1, 1);
  ObjectVisibility v;
  v.resolution = 4;
  v.terms = 2;
  for (int k = 0; k < 16; ++k) v.mean.push_back(u(rng));
  for (int k = 0; k < 32; ++k) v.basis.push_back(u(rng));
  for (int k = 0; k < 6; ++k) v.coefficients.push_back(u(rng));  // 3 vertices
  d.visibility.emplace(1, v);
  SigmoidGainTableSpec ks;
  ks.sigma_l_count = 2, ks.sigma_prime_count = 3, ks.beta_count = 4;
  std::vector<float> gains(24);
  for (auto& g : gains) g = 1.7f + 0.1f * u(rng);
  d.kappa = SigmoidGainTable::from_gains(ks, gains, 0.009);
  VisibilityMask m;
  m.resolution = 16;  // 4 blocks per vertex
  std::uniform_int_distribution<std::uint64_t> bits;
  for (int k = 0; k < 12; ++k) m.words.push_back(bits(rng));
  d.masks.emplace(1, m);
  return d;
}

std::vector<std::byte> write(const ShadingData& d) {
  bundle::BundleWriter w;
  add_shading_data_sections(w, d);
  return w.to_bytes();
}

// The same bundle without section `drop` (or with `resize` cut to half its values).
std::vector<std::byte> edited(const std::vector<std::byte>& bytes, const std::string& drop, const std::string& halve = "") {
  const auto r = bundle::BundleReader::view(bytes, "edit");
  bundle::BundleWriter w;
  for (const auto& s : r.sections()) {
    if (s.name == drop) continue;
    auto payload = r.raw(s.name);
    auto shape = s.shape;
    if (s.name == halve) {
      shape = {s.element_count() / 2};
      payload = payload.first(payload.size() / 2);
    }
    w.add_raw(s.name, s.type, shape, payload);
  }
  return w.to_bytes();
}

const std::map<size_t, size_t> kVertices{{0, 100}, {1, 3}};

// The tables' factors and the PCA basis are stored as binary16 (runtime/half_float_sections.h):
// each value back within half a unit in its 11th significant bit (2⁻²⁵ among the subnormals).
void expect_half_rounded(const std::vector<float>& want, const std::vector<float>& got) {
  ASSERT_EQ(want.size(), got.size());
  for (size_t i = 0; i < want.size(); ++i)
    ASSERT_LE(std::abs(double(got[i]) - want[i]), 1.0001 * std::max(std::abs(double(want[i])) * std::ldexp(1.0, -11), std::ldexp(1.0, -25)))
        << "value " << i << ": " << want[i] << " read as " << got[i];
}

}  // namespace

TEST(ShadingData, RoundTrips) {
  const ShadingData d = sample_data();
  const auto bytes = write(d);
  const auto r = bundle::BundleReader::view(bytes, "mem");
  ASSERT_TRUE(has_shading_data(r));
  const ShadingData back = read_shading_data(r, kVertices);
  const WeightingTables &a = d.tables.at("linen_plain"), &b = back.tables.at("linen_plain");
  EXPECT_EQ(a.tangent_samples, b.tangent_samples);
  EXPECT_EQ(a.tilts, b.tilts);
  EXPECT_EQ(a.sample_table, b.sample_table);
  EXPECT_EQ(a.lambdas, b.lambdas);
  ASSERT_EQ(a.tables.size(), b.tables.size());
  for (size_t i = 0; i < a.tables.size(); ++i) {
    EXPECT_EQ(a.tables[i].rank, b.tables[i].rank);
    expect_half_rounded(a.tables[i].u, b.tables[i].u);
    expect_half_rounded(a.tables[i].v, b.tables[i].v);
  }
  // And so the lookups agree to binary16's rounding of each factor.
  const double want = a.value(1, 37.0, glm::normalize(glm::dvec3(0.3, 0.2, 0.9)), glm::normalize(glm::dvec3(-0.5, 0.1, 0.7)));
  EXPECT_NEAR(b.value(1, 37.0, glm::normalize(glm::dvec3(0.3, 0.2, 0.9)), glm::normalize(glm::dvec3(-0.5, 0.1, 0.7))), want,
              2e-3 * std::abs(want) + 1e-6);
  const ObjectVisibility &va = d.visibility.at(1), &vb = back.visibility.at(1);
  EXPECT_EQ(va.mean, vb.mean);
  expect_half_rounded(va.basis, vb.basis);
  EXPECT_EQ(va.coefficients, vb.coefficients);
  ASSERT_TRUE(back.kappa);
  EXPECT_EQ(d.kappa->normalized_gains(), back.kappa->normalized_gains());
  EXPECT_EQ(d.kappa->kappa(0.1, 0.3, 0.4, 0.8), back.kappa->kappa(0.1, 0.3, 0.4, 0.8));
  ASSERT_EQ(back.masks.count(1), 1u);
  EXPECT_EQ(back.masks.at(1).resolution, 16);
  EXPECT_EQ(back.masks.at(1).words, d.masks.at(1).words);
}

// A reader asks for the parts its method reads: the others are not read at all (a broken section
// there goes unnoticed), and the indices alone tell what the bake holds.
TEST(ShadingData, ReadsOnlyThePartsAskedFor) {
  const ShadingData d = sample_data();
  const auto bytes = write(d);
  const auto r = bundle::BundleReader::view(bytes, "mem");
  const ShadingContents c = read_shading_contents(r);
  EXPECT_TRUE(c.tables);
  EXPECT_EQ(c.visibility, std::set<size_t>{1});
  EXPECT_EQ(c.masks, std::set<size_t>{1});

  const ShadingData tables_only = read_shading_data(r, kVertices, {}, {.tables = true, .visibility = false, .masks = false});
  EXPECT_EQ(tables_only.tables.count("linen_plain"), 1u);
  EXPECT_TRUE(tables_only.visibility.empty());
  EXPECT_FALSE(tables_only.kappa);
  EXPECT_TRUE(tables_only.masks.empty());
  const ShadingData shadows = read_shading_data(r, kVertices, {}, {.tables = false, .visibility = true, .masks = true});
  EXPECT_TRUE(shadows.tables.empty());
  EXPECT_EQ(shadows.visibility.at(1).coefficients, d.visibility.at(1).coefficients);
  EXPECT_TRUE(shadows.kappa);
  EXPECT_EQ(shadows.masks.at(1).words, d.masks.at(1).words);

  // A corrupt table is an error for a reader of tables only.
  const auto broken = edited(bytes, "T/0/v");
  const auto br = bundle::BundleReader::view(broken, "mem");
  EXPECT_THROW(read_shading_data(br, kVertices, {}, {.tables = true, .visibility = false, .masks = false}), bundle::BundleError);
  EXPECT_NO_THROW(read_shading_data(br, kVertices, {}, {.tables = false, .visibility = true, .masks = true}));
  EXPECT_TRUE(read_shading_contents(br).tables);

  const auto unmasked = edited(bytes, "bake/mask");  // weft bake --no-masks
  EXPECT_TRUE(read_shading_contents(bundle::BundleReader::view(unmasked, "mem")).masks.empty());
  const auto bad_index = edited(bytes, "", "bake/vis");
  EXPECT_THROW(read_shading_contents(bundle::BundleReader::view(bad_index, "mem")), bundle::BundleError);
}

// A part whose vertices all see the same sky compresses to its mean alone (no PCA term: a real
// third-party file, assimp-testmodels' 2CylinderEngine, has one); the reader gives every vertex
// of the mesh that mean.
TEST(ShadingData, AVisibilityOfNoTermsIsTheMeanAtEveryVertex) {
  ShadingData d = sample_data();
  ObjectVisibility& v = d.visibility.at(1);
  v.terms = 0;
  v.basis.clear();
  v.coefficients.clear();
  const auto bytes = write(d);
  const ShadingData back = read_shading_data(bundle::BundleReader::view(bytes, "mem"), kVertices);
  const ObjectVisibility& b = back.visibility.at(1);
  ASSERT_EQ(b.vertex_count(), kVertices.at(1));
  EXPECT_EQ(b.mean, v.mean);
  for (size_t vertex = 0; vertex < b.vertex_count(); ++vertex)
    for (int t = 0; t < b.terms; ++t) EXPECT_EQ(b.coefficients[vertex * b.terms + t], 0.0f);
}

TEST(ShadingData, ErrorsNameTheSection) {
  const auto bytes = write(sample_data());
  auto section_of = [](const std::vector<std::byte>& b) -> std::string {
    try {
      read_shading_data(bundle::BundleReader::view(b, "bad"), kVertices);
    } catch (const bundle::BundleError& e) {
      EXPECT_NE(std::string(e.what()).find(e.section()), std::string::npos) << e.what();
      return e.section();
    }
    return "(no error)";
  };
  EXPECT_EQ(section_of(edited(bytes, "T/0/v")), "T/0/v");
  EXPECT_EQ(section_of(edited(bytes, "", "T/0/u")), "T/0/u");
  EXPECT_EQ(section_of(edited(bytes, "vis/1/pca_basis")), "vis/1/pca_basis");
  EXPECT_EQ(section_of(edited(bytes, "", "vis/1/pca_coeffs")), "vis/1/pca_coeffs");
  EXPECT_EQ(section_of(edited(bytes, "kappa")), "kappa");
  EXPECT_EQ(section_of(edited(bytes, "bake/vis")), "bake/vis");
  EXPECT_EQ(section_of(edited(bytes, "mask/1/bits")), "mask/1/bits");
  EXPECT_EQ(section_of(edited(bytes, "", "mask/1/bits")), "mask/1/bits");
  EXPECT_EQ(section_of(edited(edited(bytes, "bake/mask"), "mask/1/bits")), "(no error)");  // masks are optional
  // Coefficients for another mesh: the vertex count is checked.
  EXPECT_EQ(section_of(bytes), "(no error)");
  try {
    read_shading_data(bundle::BundleReader::view(bytes, "other"), {{0, 100}, {1, 4}});
    ADD_FAILURE() << "a vertex-count mismatch was accepted";
  } catch (const bundle::BundleError& e) {
    EXPECT_EQ(e.section(), "vis/1/pca_coeffs");
  }
}
