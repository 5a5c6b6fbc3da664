// The camera probe plugin loader (camera/camera_probe_plugin.h): the real plugin loads and its
// source fails as a source should; a missing, foreign or other-version plugin is refused with
// a message naming the file and the package to install, and nothing is called in it.
#include <gtest/gtest.h>

#include <string>

#include "camera/camera_probe_plugin.h"

namespace weft {
namespace {

std::string refusal(const std::string& file) {
  try {
    CameraProbePlugin plugin(file);
  } catch (const CameraPluginError& e) {
    return e.what();
  }
  ADD_FAILURE() << file << " was accepted";
  return {};
}

TEST(CameraProbePlugin, LoadsTheBuiltPlugin) {
  const CameraProbePlugin plugin(WEFT_CAMERA_PROBE_PLUGIN);
  EXPECT_EQ(plugin.file(), WEFT_CAMERA_PROBE_PLUGIN);
  const auto source = plugin.open({});
  ASSERT_NE(source, nullptr);
  EXPECT_EQ(source->name().rfind("libcamera ", 0), 0u) << source->name();
}

TEST(CameraProbePlugin, MissingFileNamesThePackage) {
  const std::string why = refusal("/nonexistent/libweft-probe-libcamera.so");
  EXPECT_NE(why.find("/nonexistent/libweft-probe-libcamera.so is not installed"), std::string::npos) << why;
  EXPECT_NE(why.find("install the weft-probe-camera package"), std::string::npos) << why;
}

TEST(CameraProbePlugin, RefusesASharedObjectWithoutTheEntryPoint) {
  const std::string why = refusal(FOREIGN_PLUGIN_NONE);
  EXPECT_NE(why.find("is not a weft camera probe plugin"), std::string::npos) << why;
  EXPECT_NE(why.find("weft-probe-camera"), std::string::npos) << why;
}

TEST(CameraProbePlugin, RefusesAnotherVersionsPlugin) {
  const std::string why = refusal(FOREIGN_PLUGIN_OLD);
  EXPECT_NE(why.find("is version 0.0.0-other, this weft is " WEFT_VERSION), std::string::npos) << why;
  EXPECT_NE(why.find("weft-probe-camera package of the same version"), std::string::npos) << why;
}

TEST(CameraProbePlugin, RefusesAFileThatIsNoSharedObject) {
  const std::string why = refusal(WEFT_SOURCE_ASSETS "/fabrics/velvet.json");
  EXPECT_NE(why.find("cannot load the camera light probe's plugin"), std::string::npos) << why;
  EXPECT_NE(why.find("velvet.json"), std::string::npos) << why;
}

}  // namespace
}  // namespace weft
