// `weft bundle info` and `weft bundle verify` end to end on a bundle baked here: the exit codes
// (0 good, 2 refused), a message naming the file and what is wrong, and JSON that parses.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "bundle/bundle_reader.h"
#include "support/small_bundle.h"

namespace fs = std::filesystem;

namespace {

struct CliResult {
  int code;
  std::string out, err;
};

CliResult run_weft(const std::string& args, const fs::path& dir) {
  const fs::path err = dir / "stderr.txt";
  const std::string cmd = std::string(WEFT_BINARY) + " " + args + " 2>" + err.string();
  FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  char buf[4096];
  while (size_t n = fread(buf, 1, sizeof buf, p)) out.append(buf, n);
  const int status = pclose(p);
  std::ifstream in(err);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out, std::string(std::istreambuf_iterator<char>(in), {})};
}

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

fs::path write_file(const fs::path& p, const std::string& content) {
  std::ofstream(p, std::ios::binary) << content;
  return p;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST(BundleCli, VerifyAcceptsTheBakedBundleAndRefusesDamagedCopies) {
  const weft::test::SmallBundle b("swatch");
  ASSERT_TRUE(b.baked());
  const CliResult good = run_weft("bundle verify " + b.file().string(), b.dir());
  EXPECT_EQ(good.code, 0) << good.err;
  EXPECT_TRUE(has(good.out, "ok")) << good.out;

  const std::string bytes = read_file(b.file());
  const fs::path truncated = write_file(b.dir() / "truncated.weft", bytes.substr(0, bytes.size() / 2));
  const CliResult t = run_weft("bundle verify " + truncated.string(), b.dir());
  EXPECT_EQ(t.code, 2);
  EXPECT_TRUE(has(t.err, truncated.string()) && has(t.err, "truncated")) << t.err;

  const auto section = weft::bundle::BundleReader::open(b.file()).section("mesh/0/normals");
  std::string flipped = bytes;
  flipped[section.offset + 7] = char(flipped[section.offset + 7] ^ 0x01);
  const fs::path corrupt = write_file(b.dir() / "flipped.weft", flipped);
  const CliResult f = run_weft("bundle verify " + corrupt.string(), b.dir());
  EXPECT_EQ(f.code, 2);
  EXPECT_TRUE(has(f.err, corrupt.string()) && has(f.err, "'mesh/0/normals'") && has(f.err, "checksum mismatch"))
      << f.err;
  const CliResult fj = run_weft("bundle verify --json " + corrupt.string(), b.dir());
  EXPECT_EQ(fj.code, 2);
  const auto j = nlohmann::json::parse(fj.out);
  EXPECT_FALSE(j.at("ok").get<bool>());
  EXPECT_EQ(j.at("section"), "mesh/0/normals");
  EXPECT_TRUE(j.at("method").is_null());

  const fs::path text = write_file(b.dir() / "notes.txt", "a shopping list, not a bundle\n");
  const CliResult n = run_weft("bundle verify " + text.string(), b.dir());
  EXPECT_EQ(n.code, 2);
  EXPECT_TRUE(has(n.err, text.string()) && has(n.err, "not a Weft bundle")) << n.err;

  EXPECT_EQ(run_weft("bundle info " + corrupt.string(), b.dir()).code, 2);
  EXPECT_EQ(run_weft("bundle verify --method no_such_method " + b.file().string(), b.dir()).code, 2);
}

TEST(BundleCli, InfoAsJsonListsObjectsFabricsAndSections) {
  const weft::test::SmallBundle b("swatch");
  ASSERT_TRUE(b.baked());
  const CliResult r = run_weft("bundle info --json " + b.file().string(), b.dir());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("scene").at("name"), "swatch");
  ASSERT_EQ(j.at("objects").size(), 1u);
  EXPECT_EQ(j.at("objects")[0].at("material"), "cloth");
  EXPECT_TRUE(has(j.at("fabrics").dump(), "\"" + j.at("objects")[0].at("fabric").get<std::string>() + "\""));
  const auto reader = weft::bundle::BundleReader::open(b.file());
  ASSERT_EQ(j.at("sections").size(), reader.sections().size());
  EXPECT_EQ(j.at("sections")[0].at("name"), reader.sections()[0].name);
  EXPECT_EQ(j.at("auto_method"), "iwasaki_vertex_quadrature");
  EXPECT_TRUE(j.at("bake").contains("T"));
  const CliResult text = run_weft("bundle info " + b.file().string(), b.dir());
  EXPECT_EQ(text.code, 0);
  EXPECT_TRUE(has(text.out, "scene: swatch") && has(text.out, "sections (")) << text.out;
  EXPECT_EQ(run_weft("bundle --help", b.dir()).code, 0);
  EXPECT_EQ(run_weft("bundle info --help", b.dir()).code, 0);
}
