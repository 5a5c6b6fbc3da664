// The engineer guide's "Adding a rung" step that fills in a RuntimeMethod names exactly the
// struct's fields (render/methods/runtime_method.h): none that does not exist, none left out.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {
const fs::path kRoot = fs::path(WEFT_SOURCE_ASSETS).parent_path();

std::string text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The data members declared in `struct RuntimeMethod { … };` (one declaration a line).
std::set<std::string> struct_fields() {
  const std::string h = text(kRoot / "render/methods/runtime_method.h");
  const size_t from = h.find("struct RuntimeMethod {"), to = h.find("\n};", from);
  std::set<std::string> out;
  std::stringstream body(h.substr(from, to - from));
  const std::regex member(R"(^  [A-Za-z_:<>, ]+[ >]([a-z_]+)( = [^;]*|\{[^;]*\})?;)");
  for (std::string line; std::getline(body, line);) {
    std::smatch m;
    if (std::regex_search(line, m, member)) out.insert(m[1]);
  }
  return out;
}

// The backticked lower-case names in the guide's step "return the `RuntimeMethod` entry".
std::set<std::string> guide_fields() {
  const std::string g = text(kRoot / "docs/engineer-guide.md");
  const size_t from = g.find("return the `RuntimeMethod` entry"), to = g.find("\n3. ", from);
  const std::string step = g.substr(from, to - from);
  std::set<std::string> out;
  const std::regex name("`([a-z_]+)`");
  for (std::sregex_iterator m(step.begin(), step.end(), name), end; m != end; ++m) out.insert((*m)[1]);
  return out;
}
}  // namespace

TEST(GuideRungFields, TheGuideNamesExactlyTheRuntimeMethodsFields) {
  const std::set<std::string> fields = struct_fields(), named = guide_fields();
  ASSERT_GE(fields.size(), 5u) << "no fields read from runtime_method.h";
  ASSERT_GE(named.size(), 5u) << "no step naming the fields found in the engineer guide";
  for (const std::string& f : named) EXPECT_TRUE(fields.count(f)) << "the guide names `" << f << "`, not a RuntimeMethod field";
  for (const std::string& f : fields) EXPECT_TRUE(named.count(f)) << "the guide leaves out RuntimeMethod::" << f;
}
