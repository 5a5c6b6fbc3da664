#pragma once
// A TableSource that bakes: what the offline commands hand the runtime methods for tables a
// bundle does not hold (mizutani's, the bench's stress tables).
#include "runtime/table_source.h"

namespace weft {

TableSource table_baker();

}  // namespace weft
