#pragma once
// The kiosk's lighting changes (a probe fit, the environment knob, a new scene's light) prepared
// off the render thread, one at a time, the newest winning (kiosk/latest_request_worker.h). A
// request names the renderer it is for, so one that comes back for a renderer swapped out is
// dropped; renderers swapped out are kept until no request made for them can still run.
#include <atomic>
#include <memory>
#include <optional>
#include <vector>

#include "core/spherical_gaussian.h"
#include "gpu/scene_renderer.h"
#include "kiosk/latest_request_worker.h"

namespace weft {

class KioskLighting {
public:
  KioskLighting();
  ~KioskLighting();  // waits for the request running
  KioskLighting(const KioskLighting&) = delete;
  KioskLighting& operator=(const KioskLighting&) = delete;

  void request(const gpu::SceneRenderer& renderer, SgLighting sgs);
  // The lighting prepared for `shown`, once the worker has one; never blocks. Rethrows what the
  // preparation threw.
  std::optional<gpu::SceneRenderer::PreparedLighting> take(const gpu::SceneRenderer* shown);
  // A renderer swapped out, freed once no request for it can run.
  void retire(std::unique_ptr<gpu::SceneRenderer> renderer);

  long prepared() const { return prepared_.load(); }       // preparations finished
  double last_ms() const { return last_ms_.load(); }       // the latest one's time

private:
  struct Request {
    const gpu::SceneRenderer* renderer;
    SgLighting sgs;
  };
  struct Result {
    const gpu::SceneRenderer* renderer;
    gpu::SceneRenderer::PreparedLighting lighting;
  };
  void free_retired_when_idle();

  std::vector<std::unique_ptr<gpu::SceneRenderer>> retired_;
  std::atomic<long> prepared_{0};
  std::atomic<double> last_ms_{0};
  std::unique_ptr<LatestRequestWorker<Request, Result>> worker_;  // last: destroyed (waited for) first
};

}  // namespace weft
