#include "bench/row_measure.h"

#include <cmath>
#include <iostream>

#include "bake/writers/scene_bundle_writer.h"
#include "bench/chart.h"
#include "measure/image_metrics.h"
#include "bench/number_text.h"
#include "bench/table_stats.h"
#include "frame/frame_render.h"
#include "gpu/scene_renderer.h"
#include "image/image.h"
#include "methods/registry.h"

namespace weft::bench {

Row RowMeasure::measure(const Case& c, const LadderEntry& m, const std::string& label, const std::string& file_id,
                        std::shared_ptr<const ShadingData> bundle, const Scene* drawn) {
  const Scene& scene = drawn ? *drawn : c.scene;
  const BenchOptions& a = options_;
  const CachedReference* ref = &references_.sg_lit(c, m.thin_reference);
  std::vector<bool> surface(ref->kinds.size());
  for (size_t i = 0; i < surface.size(); ++i) surface[i] = ref->kinds[i] != PixelKind::background;
  const double exposure = auto_exposure(ref->image, surface);
  const std::string ref_png = "images/" + c.tag + (m.thin_reference ? "_thin" : "") + "_reference.png";
  if (!written_.count(ref_png)) {
    write_png(ref->image, out_ / ref_png, exposure);
    written_.insert(ref_png);
  }
  Row r;
  r.scene = c.scene_name, r.fabric = c.fabric_label, r.env = c.env, r.method = label;
  r.reference_tangent_samples = ref->tangent_samples;
  if (bundle) {
    r.bundle_bytes = table_bytes(*bundle) + visibility_bytes(*bundle), r.tables = tables_summary(*bundle);
    if (methods::method(m.name).reads_visibility_masks()) r.bundle_bytes += mask_bytes(*bundle);
  }
  r.visibility = methods::method(m.name).needs_weighting_tables();
  r.sg_count = int(c.sgs.size());
  for (const auto& o : scene.cloth_objects()) r.cloth_mesh_bytes += mesh_section_bytes(o.mesh);
  const GpuFrame speed = render_gpu_frame(scene, c.fabrics, c.sgs, m.name, a.speed_width, a.speed_height,
                                          a.speed_frames, bundle);
  renderer_ = speed.renderer;
  r.ms = speed.median_ms, r.frames = speed.frames;
  const GpuFrame acc = render_gpu_frame(scene, c.fabrics, c.sgs, m.name, a.width, a.height, 0, bundle);
  r.image = "images/" + c.tag + "_" + file_id + ".png";
  write_png(acc.image, out_ / r.image, exposure);
  r.reference_image = ref_png;
  {
    const ClothError e = cloth_error(acc.image, ref->image, ref->kinds);
    r.rmse = e.relative_rmse, r.cloth_pixels = e.cloth_pixels;
    const Image em = error_map(acc.image, ref->image, ref->kinds);
    std::vector<unsigned char> rgb(em.pixels.size() * 3);
    for (size_t i = 0; i < em.pixels.size(); ++i)
      for (int ch = 0; ch < 3; ++ch) rgb[3 * i + ch] = static_cast<unsigned char>(std::lround(255.0 * em.pixels[i][ch]));
    r.error_image = "images/" + c.tag + "_" + file_id + "_error.png";
    write_png_rgb8(em.width, em.height, rgb, out_ / r.error_image);
  }
  {
    std::vector<bool> lambertian(ref->kinds.size());
    for (size_t i = 0; i < lambertian.size(); ++i) lambertian[i] = ref->kinds[i] == PixelKind::lambertian;
    const MaskedError e = masked_error(acc.image, ref->image, lambertian);
    if (e.pixels) r.lambert_rmse = e.relative_rmse, r.lambert_ratio = e.brightness_ratio;
  }
  if (c.shadow && !m.thin_reference) {
    const MaskedError in = masked_error(acc.image, ref->image, c.shadow->shadow);
    const MaskedError beside = masked_error(acc.image, ref->image, c.shadow->band);
    r.shadow_pixels = in.pixels, r.band_pixels = beside.pixels;
    if (in.pixels) r.shadow_rmse = in.relative_rmse, r.shadow_ratio = in.brightness_ratio;
    if (beside.pixels) r.band_ratio = beside.brightness_ratio;
  }
  if (m.thin_reference) r.note = "against the thin-layer reference";
  std::cerr << "weft bench: " << c.tag << " " << label << ": " << fmt(r.ms) << " ms/frame at " << a.speed_width << "x"
            << a.speed_height << ", relative RMSE " << (r.rmse >= 0 ? fmt(r.rmse) : "n/a") << "\n";
  return r;
}

}  // namespace weft::bench
