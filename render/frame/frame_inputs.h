#pragma once
// What `weft render` draws one frame of: a scene preset (or a bundle's scene with its weighting
// tables), the fabric of each cloth object, the environment map, and the lighting made of it
// (the map itself as stratified cells, or SGs from a file or fitted to the map). Repairs
// (dropped degenerate triangles, clamped map values) are logged on stderr.
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>

#include "runtime/shading_data.h"
#include "core/fabric.h"
#include "lighting/env_map.h"
#include "reference/scene_render.h"
#include "scene/scene.h"

namespace weft {

// Bad input: an unknown scene or map, an unreadable bundle or SG file. The message names the flag.
class FrameInputError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

struct FrameInputOptions {
  std::filesystem::path assets;  // scenes/, fabrics/, envmaps/
  std::string scene;
  std::string fabric;  // empty: each cloth object's own
  std::string env;     // empty: the scene's
  std::string bundle;  // non-empty: the scene and weighting tables from this bundle
};

struct FrameInputs {
  Scene scene;
  std::map<std::string, Fabric> fabrics;  // preset → fabric of every cloth object
  std::string env;
  std::shared_ptr<EnvMap> map;
  std::shared_ptr<const ShadingData> shading;  // the bundle's tables, if one was given
};

FrameInputs load_frame_inputs(const FrameInputOptions& o);

struct FrameLightingOptions {
  std::string mode = "sg";  // "sg" or "map"
  std::string sgs_file;     // sg: SGs from this file instead of a fit
  int sg_count = 10;        // sg: SGs fitted to the map
  int map_width = 128;      // map: cells across the map
};

ReferenceLighting frame_lighting(const FrameInputs& in, const FrameLightingOptions& o);

}  // namespace weft
