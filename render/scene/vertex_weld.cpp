#include "scene/vertex_weld.h"

#include <map>
#include <tuple>

namespace weft {

std::vector<uint32_t> welded_ids(std::span<const glm::dvec3> positions, double step, const glm::dvec3& origin,
                                 std::span<const glm::dvec2> uvs) {
  using Key = std::tuple<long long, long long, long long, long long, long long>;
  std::map<Key, uint32_t> first;
  std::vector<uint32_t> id(positions.size());
  for (size_t i = 0; i < positions.size(); ++i) {
    const glm::dvec3 q = glm::round((positions[i] - origin) / step);
    const glm::dvec2 quv = uvs.empty() ? glm::dvec2(0.0) : glm::round(uvs[i] / step);
    const Key key{(long long)q.x, (long long)q.y, (long long)q.z, (long long)quv.x, (long long)quv.y};
    id[i] = first.emplace(key, uint32_t(first.size())).first->second;
  }
  return id;
}

}  // namespace weft
