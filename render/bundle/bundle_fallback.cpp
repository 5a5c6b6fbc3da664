#include "bundle/bundle_fallback.h"

#include <algorithm>
#include <optional>

#include "files/atomic_file.h"

namespace weft::bundle {
namespace {

BundleReader open_accepted(const std::filesystem::path& file, const FallbackOptions& options) {
  BundleReader r = options.read_into_memory ? BundleReader::read(file) : BundleReader::open(file);
  if (options.accept) options.accept(r);
  return r;
}

// Whether the last good copy already holds exactly these bytes (saves a flash write per boot).
bool same_as_last_good(const std::filesystem::path& copy, std::span<const std::byte> bytes) {
  try {
    const BundleReader old = BundleReader::open(copy);
    return std::ranges::equal(old.bytes(), bytes);
  } catch (const BundleError&) {
    return false;
  }
}

}  // namespace

std::filesystem::path last_good_path(const std::filesystem::path& last_good_dir) {
  return last_good_dir / "last-good.weftbundle";
}

void save_as_last_good(const BundleReader& bundle, const std::filesystem::path& source,
                       const std::filesystem::path& last_good_dir, const LogSink& log) {
  const std::filesystem::path copy = last_good_path(last_good_dir);
  if (same_as_last_good(copy, bundle.bytes())) return;
  try {
    std::filesystem::create_directories(last_good_dir);
    write_file_atomically(copy, bundle.bytes());
    log(LogPriority::info, "bundle " + source.string() + " verified; saved as the last good bundle " + copy.string());
  } catch (const std::exception& e) {
    // The bundle is fine; only the safety copy could not be refreshed.
    log(LogPriority::warning, "bundle " + source.string() + " verified, but the last good copy was not updated: " + e.what());
  }
}

OpenedBundle open_bundle_with_fallback(const std::filesystem::path& primary,
                                       const std::filesystem::path& last_good_dir,
                                       const FallbackOptions& options) {
  const auto log = [&](LogPriority priority, const std::string& line) {
    if (options.log)
      options.log(priority, line);
    else
      log_line("weft", priority, line);
  };
  const std::filesystem::path copy = last_good_path(last_good_dir);

  std::string primary_error;
  try {
    BundleReader bundle = open_accepted(primary, options);
    save_as_last_good(bundle, primary, last_good_dir, log);
    return {std::move(bundle), primary, false, ""};
  } catch (const BundleError& e) {
    primary_error = e.what();
  }

  log(LogPriority::warning, primary_error + "; falling back to the last good bundle " + copy.string());
  try {
    BundleReader bundle = open_accepted(copy, options);
    log(LogPriority::warning, "using the last good bundle " + copy.string());
    return {std::move(bundle), copy, true, primary_error};
  } catch (const BundleError& e) {
    log(LogPriority::error, std::string("the last good bundle is unusable too: ") + e.what());
    throw BundleError(primary.string(), "file", "",
                      "no usable bundle: " + primary_error + "; last good copy: " + e.what());
  }
}

}  // namespace weft::bundle
