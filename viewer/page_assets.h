// The files a viewer page is made of, built into the executable (page_assets.cpp), so writing a
// viewer needs nothing at run time and the folder stands alone: three.js and its orbit controls
// from Debian's libjs-three (r111), and the page's own template, style and script in
// viewer/page/.
#pragma once

#include <string_view>

namespace rtlab::viewer {

struct PageAssets {
    std::string_view three;          // three.min.js
    std::string_view orbitControls;  // examples/js/controls/OrbitControls.js
    std::string_view html;           // viewer/page/index.html, with the markers below
    std::string_view css;            // viewer/page/viewer.css
    std::string_view script;         // viewer/page/viewer.js
};

const PageAssets& pageAssets();

}  // namespace rtlab::viewer
