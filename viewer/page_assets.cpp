#include "viewer/page_assets.h"

// Each file is assembled into the read-only data section as it is (.incbin), with a NUL after
// it; CMake passes the paths and recompiles this file when one changes (viewer/CMakeLists.txt).
#define RTLAB_EMBED(symbol, path)                                                       \
    asm(".pushsection .rodata\n"                                                        \
        ".balign 16\n"                                                                  \
        ".global " #symbol "_begin\n" #symbol "_begin:\n"                               \
        ".incbin \"" path "\"\n"                                                        \
        ".global " #symbol "_end\n" #symbol "_end:\n"                                   \
        ".byte 0\n"                                                                     \
        ".popsection\n");                                                               \
    extern "C" const char symbol##_begin[];                                             \
    extern "C" const char symbol##_end[];

RTLAB_EMBED(rtlab_viewer_three, RTLAB_THREE_JS)
RTLAB_EMBED(rtlab_viewer_orbit, RTLAB_ORBIT_CONTROLS_JS)
RTLAB_EMBED(rtlab_viewer_html, RTLAB_VIEWER_PAGE_DIR "/index.html")
RTLAB_EMBED(rtlab_viewer_css, RTLAB_VIEWER_PAGE_DIR "/viewer.css")
RTLAB_EMBED(rtlab_viewer_js, RTLAB_VIEWER_PAGE_DIR "/viewer.js")

namespace rtlab::viewer {

const PageAssets& pageAssets() {
    static const PageAssets assets{
        {rtlab_viewer_three_begin, size_t(rtlab_viewer_three_end - rtlab_viewer_three_begin)},
        {rtlab_viewer_orbit_begin, size_t(rtlab_viewer_orbit_end - rtlab_viewer_orbit_begin)},
        {rtlab_viewer_html_begin, size_t(rtlab_viewer_html_end - rtlab_viewer_html_begin)},
        {rtlab_viewer_css_begin, size_t(rtlab_viewer_css_end - rtlab_viewer_css_begin)},
        {rtlab_viewer_js_begin, size_t(rtlab_viewer_js_end - rtlab_viewer_js_begin)},
    };
    return assets;
}

}  // namespace rtlab::viewer
