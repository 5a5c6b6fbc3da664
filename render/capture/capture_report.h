#pragma once
// What `weft capture DIR` writes: the fabric file (the family preset's file with the fitted
// threads, in the format of assets/fabrics/README.md, so `weft bake --fabric` takes it) with the
// fit's residual and each parameter's 1σ in an extra `capture` field; and a side-by-side PNG,
// one row per photo: the rectified swatch, the fitted model under the captured lighting, and
// their difference ×4.
#include <filesystem>
#include <optional>
#include <string>

#include "capture/appearance_check.h"
#include "capture/capture_fit.h"

namespace weft {

// `check`, when given, goes into the `capture` field as `appearance_check`.
void write_fitted_fabric(const CaptureFitResult& result, const std::filesystem::path& presets_dir,
                         const std::filesystem::path& file, const std::optional<AppearanceCheck>& check = std::nullopt);
void write_side_by_side(const CaptureFitResult& result, const std::filesystem::path& file);
// The fit for a person in a terminal: the weave family, the residual, each thread's parameters
// with their 1σ, and the appearance check when given; one line each.
std::string fit_summary(const CaptureFitResult& result, const std::optional<AppearanceCheck>& check = std::nullopt);

}  // namespace weft
