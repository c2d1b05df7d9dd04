// tinygltf's implementation from Debian's header (libtinygltf-dev), compiled here so that the
// fuzzer sees its coverage and the sanitizers its memory accesses; Debian's prebuilt
// libtinygltf.so is neither. Debian ships no stb_image, and rtlab never decodes or writes
// images, so the two image hooks the TinyGLTF constructor installs by default refuse.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#include <tiny_gltf.h>

namespace tinygltf {

bool LoadImageData(Image*, const int, std::string* err, std::string*, int, int, const unsigned char*, int, void*) {
    if (err) *err += "image decoding is not built in\n";
    return false;
}

bool WriteImageData(const std::string*, const std::string*, const Image*, bool, std::string*, void*) {
    return false;
}

}  // namespace tinygltf
