// What CMake configured this build with. The values live in this one small file because they
// differ between copies of the tree (a student release, the tests' scratch copies): a file
// whose compile command holds them is compiled again in every copy instead of coming from the
// compiler cache (docs/building.md).
#pragma once

namespace rtlab::cli {

// The repository this executable was built from: the default --root of `rtlab grade`, --from of
// `rtlab release`, and the folder `rtlab view` reads its scenes from.
const char* repositoryDir();

// The project's version (CMakeLists.txt), for --version.
const char* version();

}  // namespace rtlab::cli
