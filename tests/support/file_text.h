#pragma once
// A file's bytes as a string, for tests that read back what the code under test wrote
// (empty when the file cannot be opened: the test's own expectation then fails).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace weft::test {

inline std::string read_all(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace weft::test
