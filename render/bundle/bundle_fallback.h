#pragma once
// Boot-time bundle selection for the kiosk (docs/design.md §5): use the freshly baked bundle if it
// verifies, else the last good copy, and say why. A bundle that verifies becomes the new last
// good copy (replaced atomically, so a power cut never leaves a half-written one).
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

#include "bundle/bundle_reader.h"
#include "journal/journal_log.h"

namespace weft::bundle {

struct FallbackOptions {
  // Extra checks by the consumer (required sections present, shapes it can use...); throw
  // BundleError to reject the bundle. A rejected primary is not saved as last good.
  std::function<void(const BundleReader&)> accept;
  // Where operator-readable lines go (the kiosk sends them to the journal); default: stderr.
  LogSink log;
  // Read the files into memory (BundleReader::read) instead of mapping them: for a consumer that
  // keeps running while the file may be rewritten in place.
  bool read_into_memory = false;
};

struct OpenedBundle {
  BundleReader bundle;
  std::filesystem::path file;   // the file actually opened
  bool is_last_good = false;    // true when the primary was unusable
  std::string primary_error;    // why the primary was unusable ("" when it was used)
};

// The last good copy kept in `last_good_dir`.
std::filesystem::path last_good_path(const std::filesystem::path& last_good_dir);

// Makes `bundle` (read from `source`) the last good copy in `last_good_dir`, unless the copy
// already holds the same bytes; logs what it did, or (warning) why the copy was not updated.
void save_as_last_good(const BundleReader& bundle, const std::filesystem::path& source,
                       const std::filesystem::path& last_good_dir, const LogSink& log);

// Opens `primary`; on any BundleError opens the last good copy instead. Throws BundleError
// (with both reasons) only when neither can be used.
OpenedBundle open_bundle_with_fallback(const std::filesystem::path& primary,
                                       const std::filesystem::path& last_good_dir,
                                       const FallbackOptions& options = {});

}  // namespace weft::bundle
