#pragma once
// The scene renderer as the kiosk draws a bundle, at boot and for each content update: the
// showroom backdrop, and the resolved weave for close-ups where the method can draw it.
#include <memory>
#include <vector>

#include "core/fabric.h"
#include "gpu/scene_renderer.h"
#include "methods/runtime_method.h"
#include "runtime/shading_data.h"
#include "runtime/scene_bundle.h"

namespace weft {

// The base fabric each cloth object wears (object_base_fabric: its colour on its preset), in the
// scene's order of cloth objects.
std::vector<Fabric> cloth_fabrics(const SceneBundle& sb);

// Needs the GL context current. A renderer that cannot draw the weave (a see-through method; a
// cloth mesh without UVs) shows the fabric level up close, with a warning.
std::unique_ptr<gpu::SceneRenderer> make_kiosk_renderer(const SceneBundle& sb, const std::vector<Fabric>& cloth,
                                                        const methods::RuntimeMethod& method,
                                                        std::shared_ptr<const ShadingData> shading);

// The weave layer's range (SceneRenderer::set_weave_range): the kiosk's zoom path from the scene's
// view to `closeup` (camera_zoom.h's dolly), each camera turned about the turntable's pivot as
// the kiosk turns it, on a width × height frame. Logs the cloth objects out of reach.
void arm_weave_range(gpu::SceneRenderer& renderer, const SceneBundle& sb, const Camera& closeup, int width, int height);

}  // namespace weft
