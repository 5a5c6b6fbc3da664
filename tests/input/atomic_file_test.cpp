// files/atomic_file.h: the target holds the old or the new contents, never a temporary beside it.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>

#include "files/atomic_file.h"

using namespace weft;

namespace {

std::filesystem::path fresh_dir(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / ("weft_atomic_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A file holding "old" alone in a fresh directory.
std::filesystem::path old_file(const std::string& name, const std::string& file_name) {
  const auto file = fresh_dir(name) / file_name;
  write_file_atomically(file, std::string_view("old"));
  return file;
}

size_t entries(const std::filesystem::path& dir) {
  return size_t(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()));
}

}  // namespace

TEST(AtomicFile, TextReplacesTheTarget) {
  const auto file = old_file("text", "a.json");
  write_file_atomically(file, std::string_view("new contents"));
  EXPECT_EQ(read(file), "new contents");
  EXPECT_EQ(entries(file.parent_path()), 1u);
}

TEST(AtomicFile, PathWriterFillsTheTemporary) {
  const auto file = old_file("writer", "b.png");
  write_file_atomically(file, [&](const std::filesystem::path& temporary) {
    EXPECT_NE(temporary, file);
    EXPECT_EQ(temporary.parent_path(), file.parent_path());
    std::ofstream(temporary, std::ios::binary) << "written by a library";
  });
  EXPECT_EQ(read(file), "written by a library");
  EXPECT_EQ(entries(file.parent_path()), 1u);
}

TEST(AtomicFile, AFailedWriterLeavesTheOldContents) {
  const auto file = old_file("failed", "c.exr");
  EXPECT_THROW(write_file_atomically(file,
                                     [](const std::filesystem::path& temporary) {
                                       std::ofstream(temporary) << "half";
                                       throw std::runtime_error("library failed");
                                     }),
               std::runtime_error);
  EXPECT_EQ(read(file), "old");
  EXPECT_EQ(entries(file.parent_path()), 1u);
}

TEST(AtomicFile, AMissingDirectoryThrows) {
  EXPECT_THROW(write_file_atomically(fresh_dir("missing") / "no" / "d.txt", std::string_view("x")), std::system_error);
}
