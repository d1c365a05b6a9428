// The one file of the tool compiled for each program (raylab, raylab-reference): which labs it was
// linked with, and from where (framework/CMakeLists.txt sets both).
#include "build_info.h"

namespace raylab::build {

const char* const kImpl = RAYLAB_IMPL;
const char* const kLabOrigins = RAYLAB_LAB_ORIGINS;

} // namespace raylab::build
