// Where a viewer is written: the rule of `rtlab view -o DIR` and of the report's links. A folder
// that exists must be empty or a viewer (it holds kViewerMarker); the new one is written beside
// it and renamed into place, so a failure leaves the old one, or nothing, never half of one.
#pragma once

#include <filesystem>

namespace rtlab::viewer {

class ViewerFolder {
public:
    // Throws rtlab::Error "DIR: ..." when dir may not be written.
    explicit ViewerFolder(std::filesystem::path dir);
    ~ViewerFolder();  // removes the scratch folder unless committed
    ViewerFolder(const ViewerFolder&) = delete;
    ViewerFolder& operator=(const ViewerFolder&) = delete;

    // Where to write the files until commit.
    const std::filesystem::path& scratch() const { return scratch_; }
    // Marks the scratch folder as a viewer and puts it in dir's place.
    void commit();

private:
    std::filesystem::path dir_, scratch_;
    bool committed_ = false;
};

// Throws rtlab::Error when dir exists and is neither empty nor a viewer.
void checkViewerTarget(const std::filesystem::path& dir);

}  // namespace rtlab::viewer
