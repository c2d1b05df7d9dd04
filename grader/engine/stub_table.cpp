#include "grader/engine/stub_table.h"

#include <algorithm>
#include <stdexcept>

namespace rtlab::grader {

StubTable::StubTable(std::string assignment, std::string folder, std::vector<StubFile> files)
    : assignment_(std::move(assignment)), folder_(std::move(folder)), files_(std::move(files)) {}

std::string StubTable::path(const std::string& file) const { return "assignments/" + folder_ + "/" + file; }

const StubFile& StubTable::fileOf(const std::string& function) const {
    for (const StubFile& f : files_)
        if (std::find(f.functions.begin(), f.functions.end(), function) != f.functions.end()) return f;
    throw std::logic_error(assignment_ + "'s stub table has no " + function);
}

std::string StubTable::function(const std::string& function) const {
    fileOf(function);  // one the table has
    return assignment_ + " " + function;
}

std::string StubTable::name(const std::string& function) const { return this->function(function) + " (" + path(fileOf(function).file) + ")"; }

std::string StubTable::names(std::initializer_list<std::string> functions) const {
    std::string list, file;
    for (const std::string& f : functions) {
        const std::string& of = fileOf(f).file;
        if (!file.empty() && of != file) throw std::logic_error(assignment_ + ": " + f + " is not in " + file);
        file = of;
        list += (list.empty() ? "" : " and ") + f;
    }
    return assignment_ + " " + list + " (" + path(file) + ")";
}

std::string StubTable::file(const std::string& file, const std::string& label) const {
    if (std::none_of(files_.begin(), files_.end(), [&](const StubFile& f) { return f.file == file; }))
        throw std::logic_error(assignment_ + "'s stub table has no file " + file);
    return assignment_ + " " + label + " (" + path(file) + ")";
}

}  // namespace rtlab::grader
