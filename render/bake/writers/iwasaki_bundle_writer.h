#pragma once
// Writes the weighting-table sections (runtime/iwasaki_bundle.h: names, data, reader) into a bundle.
#include "bundle/bundle_writer.h"
#include "runtime/iwasaki_bundle.h"

namespace weft {

// Adds the sections.
void add_iwasaki_sections(bundle::BundleWriter& writer, const IwasakiBundleData& data);

}  // namespace weft
