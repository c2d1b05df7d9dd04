// The contract every parser under fuzzing keeps: a rejected input ends in one rtlab::Error whose
// message is one line starting with the file's path. Anything else (another exception, a
// message over several lines or without the path) aborts, so libFuzzer reports it.
#pragma once

#include "framework/core/error.h"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace rtlab::fuzz {

inline void checkOneLineError(const Error& error, const std::string& path) {
    std::string message = error.what();
    if (message.rfind(path, 0) != 0 || message.find_first_of("\r\n") != std::string::npos) {
        std::fprintf(stderr, "rejected with a malformed error message: [%s]\n", message.c_str());
        std::abort();
    }
}

// Runs parse(path); an rtlab::Error is a rejection and must keep the contract.
template <typename Parse>
void parseOrReject(const std::string& path, Parse parse) {
    try {
        parse(path);
    } catch (const Error& error) {
        checkOneLineError(error, path);
    }
}

}  // namespace rtlab::fuzz
