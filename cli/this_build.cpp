#include "cli/this_build.h"

namespace rtlab::cli {

const char* repositoryDir() { return RTLAB_REPOSITORY_DIR; }

const char* version() { return RTLAB_VERSION; }

}  // namespace rtlab::cli
