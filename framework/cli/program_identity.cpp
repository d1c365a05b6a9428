// The one file of the tool compiled for each program (raylab, raylab-reference): which labs it was
// linked with, and from where, and the tree it was built from (framework/CMakeLists.txt sets them).
#include "build_info.h"

namespace raylab::build {

const char* const kImpl = RAYLAB_IMPL;
const char* const kLabOrigins = RAYLAB_LAB_ORIGINS;
const char* const kSourceDir = RAYLAB_SOURCE_DIR;
const char* const kBinaryDir = RAYLAB_BINARY_DIR;
const char* const kBuildDir = RAYLAB_BUILD_DIR;
const char* const kBuildType = RAYLAB_BUILD_TYPE;
const char* const kVersion = RAYLAB_VERSION;

} // namespace raylab::build
