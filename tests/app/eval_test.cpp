// The reference quadrature's invariants and the `weft eval` command-line contract.
// (Its accuracy against an independent integration: reference_quadrature_test.cpp.)
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>

#include <nlohmann/json.hpp>

#include "bake/tables/table_baker.h"
#include "core/cloth_bsdf.h"
#include "methods/registry.h"
#include "reference/sg_quadrature.h"
#include "runtime/paper_tangent_samples.h"

using namespace weft;
constexpr double kPi = std::numbers::pi;

namespace {

Fabric preset(const std::string& name) { return load_fabric_preset(name, WEFT_SOURCE_ASSETS "/fabrics"); }

dvec3 view_at(double theta_deg, double phi_deg) {
  const double t = glm::radians(theta_deg), p = glm::radians(phi_deg);
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

double relative_difference(const dvec3& a, const dvec3& b) { return glm::length(a - b) / glm::length(b); }

}  // namespace

TEST(ReferenceQuadrature, LinearInTheLight) {
  // On one fixed grid the quadrature is linear in the lighting: one SG equals two at half μ.
  const ClothBsdf bsdf(preset("linen_plain"), 16);
  const dvec3 wo = view_at(30, 0);
  const SphericalGaussian g{glm::normalize(dvec3(0.1, 0.2, 1)), 8.0, dvec3(1.0)};
  SgQuadratureOptions fixed;
  fixed.min_polar = 64;
  fixed.max_polar = 64;  // one grid level: exact linearity
  const dvec3 one = integrate_sg_lighting(bsdf, SurfaceFrame{}, wo, std::vector{g}, fixed).radiance;
  SphericalGaussian half = g;
  half.amplitude *= 0.5;
  const dvec3 two = integrate_sg_lighting(bsdf, SurfaceFrame{}, wo, std::vector{half, half}, fixed).radiance;
  EXPECT_NEAR(relative_difference(two, one), 0.0, 1e-12);
}

TEST(ReferenceQuadrature, ShadowedHalfOfTheSkyDropsItsLight) {
  // Visibility hook: blocking every direction with y > 0 must remove exactly the light an SG
  // confined to y > 0 brings (to within its negligible tail on the other side).
  const ClothBsdf bsdf(preset("silk_shot"), 16);
  const dvec3 wo = view_at(40, -90);
  const SgLighting sgs = {{glm::normalize(dvec3(0, 0.8, 0.6)), 200.0, dvec3(1.0)}};
  SgQuadratureOptions blocked;
  blocked.visible = [](const dvec3& w) { return w.y <= 0.0; };
  const dvec3 open = integrate_sg_lighting(bsdf, SurfaceFrame{}, wo, sgs).radiance;
  const dvec3 shut = integrate_sg_lighting(bsdf, SurfaceFrame{}, wo, sgs, blocked).radiance;
  EXPECT_GT(open.g, 0.0);
  EXPECT_LT(shut.g, 1e-6 * open.g);
}

// ---- the command-line contract ----

namespace {
struct CommandResult {
  int code;
  std::string out, err;
};
CommandResult run_weft(const std::string& args) {
  // Per-test names: ctest runs each test of this file as its own process, in parallel.
  const std::string tag = testing::UnitTest::GetInstance()->current_test_info()->name();
  const std::string out = testing::TempDir() + "weft_out_" + tag + ".txt", err = testing::TempDir() + "weft_err_" + tag + ".txt";
  const int status = std::system((std::string(WEFT_BINARY) + " " + args + " >" + out + " 2>" + err).c_str());
  auto slurp = [](const std::string& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
}
}  // namespace

TEST(EvalCommand, PrintsTheContractJsonMatchingTheLibrary) {
  const CommandResult r = run_weft("eval --fabric velvet --view 0.5,0.2,0.8 --sg -0.3,0.1,0.9,20,1,1,1");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("method"), "reference");
  ASSERT_EQ(j.at("radiance").size(), 3u);
  const ClothBsdf bsdf(preset("velvet"), 64);
  const SgLighting sgs = {{glm::normalize(dvec3(-0.3, 0.1, 0.9)), 20.0, dvec3(1.0)}};
  const dvec3 lib = integrate_sg_lighting(bsdf, SurfaceFrame{}, glm::normalize(dvec3(0.5, 0.2, 0.8)), sgs).radiance;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(j["radiance"][c].get<double>(), lib[c], 1e-12 + 1e-9 * lib[c]);
}

// Every registered method with a C++ evaluation is evaluable, through that evaluation: the
// command's value is RuntimeMethod::cpu's with the paper's tangent samples and the bench's tables.
TEST(EvalCommand, EveryMethodWithACppEvaluationGivesThatEvaluation) {
  const Fabric fabric = preset("linen_plain");
  const dvec3 wo = glm::normalize(dvec3(0.5, 0.2, 0.8));
  const SgLighting sgs = {{glm::normalize(dvec3(-0.3, 0.1, 0.9)), 20.0, dvec3(1.0)}};
  int evaluated = 0;
  for (const auto& m : methods::registry()) {
    const CommandResult r = run_weft("eval --fabric linen_plain --view 0.5,0.2,0.8 --sg -0.3,0.1,0.9,20,1,1,1 --method " + m.name);
    if (!m.cpu) {
      EXPECT_EQ(r.code, 2) << m.name << " has no C++ evaluation yet eval took it";
      EXPECT_NE(r.err.find("not available for eval"), std::string::npos) << r.err;
      continue;
    }
    ASSERT_EQ(r.code, 0) << m.name << ": " << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("method"), m.name);
    const ClothBsdf bsdf(fabric, paper_tangent_samples(fabric));
    const dvec3 lib = m.cpu(bsdf, SurfaceFrame{}, wo, sgs, table_baker()).radiance;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(j["radiance"][c].get<double>(), lib[c], 1e-12 + 1e-9 * lib[c]) << m.name;
    ++evaluated;
  }
  EXPECT_GE(evaluated, 5);
}

TEST(EvalCommand, RejectsBadInputWithExitTwoNamingTheArgument) {
  const std::string sg = " --sg 0,0,1,10,1,1,1";
  struct Case {
    std::string args, mentions;
  };
  for (const Case& c : std::vector<Case>{
           {"eval --view 0.5,0.2,-0.8" + sg, "--view"},
           {"eval --view 0,0,0" + sg, "--view"},
           {"eval --view 0,0,1 --sg 0,0,0,10,1,1,1", "--sg"},
           {"eval --view 0,0,1 --sg 0,0,1,-5,1,1,1", "sharpness"},
           {"eval --view 0,0,1 --sg 0,0,1,5,1,-1,1", "amplitude"},
           {"eval --view 0,0,1 --sg 0,0,1,nan,1,1,1", "--sg"},
           {"eval --view 0,0,1 --sg 0,0,1,5,1,1", "--sg"},
           {"eval --fabric tweed --view 0,0,1" + sg, "tweed"},
           {"eval --view 0,0,1" + sg + " --method magic", "--method"},
           {"eval --view 0,0,1", "--sg"},
       }) {
    const CommandResult r = run_weft(c.args);
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.mentions), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << c.args;
  }
}

TEST(EvalCommand, HelpListsSubcommandsAndExitsZero) {
  CommandResult r = run_weft("--help");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("eval"), std::string::npos);
  r = run_weft("eval --help");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("--sg"), std::string::npos);
}
