#include "panel/gpio_knob_source.h"

namespace weft::input {
namespace {
constexpr int kWaitMs = 100;  // bounds how long stop() waits
uint32_t to_ms(uint64_t ns) { return static_cast<uint32_t>(ns / 1000000ull); }
}  // namespace

GpioKnobSource::GpioKnobSource(GpioPanelConfig config, GpioOpener opener, LogSink log, Backoff backoff)
    : config_(std::move(config)),
      opener_(opener ? std::move(opener) : GpioOpener(open_gpiod_lines)),
      log_(log ? std::move(log) : stderr_log()),
      backoff_(backoff) {}

GpioKnobSource::~GpioKnobSource() { stop(); }

std::string GpioKnobSource::describe() const { return "GPIO knobs on " + config_.chip; }

void GpioKnobSource::start(KnobSink sink) {
  stop();
  stop_.clear();
  thread_ = std::thread([this, sink = std::move(sink)] { run(sink); });
}

void GpioKnobSource::stop() {
  stop_.request();
  if (thread_.joinable()) thread_.join();
}

void GpioKnobSource::run(KnobSink sink) {
  Backoff backoff = backoff_;
  bool announced = false;
  std::vector<GpioEdge> edges;
  while (!stop_.requested()) {
    std::string why;
    auto lines = opener_(config_, why);
    if (!lines) {
      ++open_failures_;
      const auto wait = backoff.next();
      if (!announced) {
        log_(LogPriority::warning, describe() + " unavailable (" + why + "); GPIO knobs stay off, retrying in the background");
        announced = true;
      }
      if (stop_.wait_for(wait)) break;
      continue;
    }
    backoff.succeeded();
    announced = false;
    open_ = true;
    log_(LogPriority::info, describe() + " ready");
    GpioPanelDecoder decoder(config_);
    decoder.reset(lines->levels(), to_ms(lines->now_ns()));
    KnobEvent event;
    while (!stop_.requested()) {
      edges.clear();
      const int settle = decoder.settle_timeout_ms();
      const auto r = lines->wait(settle >= 0 ? settle : kWaitMs, edges);
      if (r == GpioLines::Wait::error) {
        log_(LogPriority::warning, describe() + " failed (" + lines->last_error() + "); reopening");
        break;
      }
      for (const GpioEdge& e : edges)
        if (decoder.on_edge(e.offset, e.level, to_ms(e.time_ns), event)) sink(event);
      if (decoder.on_idle(to_ms(lines->now_ns()), event)) sink(event);
    }
    open_ = false;
    if (!stop_.requested() && stop_.wait_for(backoff.next())) break;
  }
}

}  // namespace weft::input
