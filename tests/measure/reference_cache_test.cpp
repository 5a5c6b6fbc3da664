// The bench's cached tangent-sample choices (measure/reference_cache.h): a choice reads back as
// written, and a file that is not one (another magic, truncated, a stray word) reads as none,
// so the reference is chosen again rather than from a broken file.
#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>

#include "measure/reference_cache.h"

using namespace weft;
using namespace weft::bench;

namespace {

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("weft_reference_cache_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir / name;
}

void write_text(const std::filesystem::path& file, const std::string& text) { std::ofstream(file) << text; }

}  // namespace

TEST(ReferenceCache, ConvergenceChoiceReadsBackAsWritten) {
  TangentConvergence c;
  c.samples = 64, c.converged = true, c.cloth_pixels = 321, c.seconds = 44.375;
  c.steps = {{32, 64, 0.0158}, {64, 128, 0.00572}};
  const auto file = scratch("choice.txt");
  store_convergence(file, c);
  const auto back = load_convergence(file);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->samples, 64);
  EXPECT_TRUE(back->converged);
  EXPECT_EQ(back->cloth_pixels, 321u);
  EXPECT_DOUBLE_EQ(back->seconds, 44.375);
  ASSERT_EQ(back->steps.size(), 2u);
  EXPECT_EQ(back->steps[1].samples, 64);
  EXPECT_EQ(back->steps[1].finer, 128);
  EXPECT_DOUBLE_EQ(back->steps[1].relative_change, 0.00572);
  std::filesystem::remove_all(file.parent_path());
}

TEST(ReferenceCache, BrokenConvergenceFilesReadAsNone) {
  EXPECT_FALSE(load_convergence(scratch("missing.txt")));
  const auto file = scratch("broken.txt");
  write_text(file, "WEFTREF1\nsamples 64 converged 1 cloth_pixels 3 seconds 1\n");
  EXPECT_FALSE(load_convergence(file));
  write_text(file, "WEFTNJ1\nsamples 64 converged 1 cloth_pixels");
  EXPECT_FALSE(load_convergence(file));
  write_text(file, "WEFTNJ1\nsamples 0 converged 1 cloth_pixels 3 seconds 1\n");
  EXPECT_FALSE(load_convergence(file));
  write_text(file, "WEFTNJ1\nsamples 64 converged 1 cloth_pixels 3 seconds 1\nstep 32 64 0.01\nnote 1 2 3\n");
  EXPECT_FALSE(load_convergence(file));
  write_text(file, "WEFTNJ1\nsamples 64 converged 1 cloth_pixels 3 seconds 1\nstep 32 64\n");
  EXPECT_FALSE(load_convergence(file));
  std::filesystem::remove_all(file.parent_path());
}
