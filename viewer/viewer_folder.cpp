#include "viewer/viewer_folder.h"

#include "framework/core/error.h"
#include "viewer/case_view.h"

#include <fstream>
#include <unistd.h>

namespace rtlab::viewer {

namespace fs = std::filesystem;

void checkViewerTarget(const fs::path& dir) {
    std::error_code ec;
    fs::file_status status = fs::symlink_status(dir, ec);
    if (!fs::exists(status)) {
        fs::path parent = fs::absolute(dir).parent_path();
        if (!fs::is_directory(parent)) throw Error(dir.string() + ": its folder " + parent.string() + " does not exist");
        return;
    }
    if (!fs::is_directory(status)) throw Error(dir.string() + ": exists and is not a folder (not overwritten)");
    if (fs::is_empty(dir, ec) || fs::is_regular_file(dir / kViewerMarker)) return;
    throw Error(dir.string() + ": exists and is not a viewer folder (not overwritten; choose a new folder)");
}

ViewerFolder::ViewerFolder(fs::path dir) : dir_(std::move(dir)) {
    checkViewerTarget(dir_);
    fs::path absolute = fs::absolute(dir_);
    std::string base = absolute.filename().empty() ? absolute.parent_path().filename().string() : absolute.filename().string();
    fs::path parent = absolute.filename().empty() ? absolute.parent_path().parent_path() : absolute.parent_path();
    scratch_ = parent / ("." + base + ".writing-" + std::to_string(getpid()));
    std::error_code ec;
    fs::remove_all(scratch_, ec);
    if (!fs::create_directory(scratch_, ec)) throw Error(dir_.string() + ": cannot create " + scratch_.string() + ": " + ec.message());
}

ViewerFolder::~ViewerFolder() {
    if (committed_) return;
    std::error_code ec;
    fs::remove_all(scratch_, ec);
}

void ViewerFolder::commit() {
    {
        std::ofstream marker(scratch_ / kViewerMarker);
        marker << "written by rtlab view (docs/viewer.md); rtlab may replace this folder\n";
        if (!marker) throw Error(scratch_.string() + ": cannot write");
    }
    std::error_code ec;
    if (fs::exists(fs::symlink_status(dir_))) {
        checkViewerTarget(dir_);  // still empty or a viewer
        fs::remove_all(dir_, ec);
        if (ec) throw Error(dir_.string() + ": cannot replace the old viewer: " + ec.message());
    }
    fs::rename(scratch_, dir_, ec);
    if (ec) throw Error(dir_.string() + ": cannot move the new viewer into place: " + ec.message());
    committed_ = true;
}

}  // namespace rtlab::viewer
