#include "kiosk/kiosk_lighting.h"

#include <chrono>

namespace weft {

KioskLighting::KioskLighting()
    : worker_(std::make_unique<LatestRequestWorker<Request, Result>>([this](const Request& q) {
        const auto t0 = std::chrono::steady_clock::now();
        Result r{q.renderer, q.renderer->prepare_lighting(q.sgs)};
        last_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        ++prepared_;
        return r;
      })) {}

KioskLighting::~KioskLighting() = default;

void KioskLighting::request(const gpu::SceneRenderer& renderer, SgLighting sgs) {
  worker_->request({&renderer, std::move(sgs)});
}

std::optional<gpu::SceneRenderer::PreparedLighting> KioskLighting::take(const gpu::SceneRenderer* shown) {
  std::optional<Result> done;
  try {
    done = worker_->take();
  } catch (...) {
    free_retired_when_idle();
    throw;
  }
  std::optional<gpu::SceneRenderer::PreparedLighting> out;
  // Requests run in order: once one made for the renderer shown is done, none for a retired one runs.
  if (done && done->renderer == shown) {
    retired_.clear();
    out = std::move(done->lighting);
  }
  free_retired_when_idle();
  return out;
}

void KioskLighting::retire(std::unique_ptr<gpu::SceneRenderer> renderer) { retired_.push_back(std::move(renderer)); }

void KioskLighting::free_retired_when_idle() {
  if (!retired_.empty() && worker_->idle()) retired_.clear();
}

}  // namespace weft
