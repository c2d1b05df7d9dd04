// rtlab-sandbox-start: what the grader spawns for each worker (grader/engine/sandbox_start.h).
// Not a command for people; run by hand it explains itself and exits.
#include "grader/engine/sandbox_start.h"

#include <iostream>
#include <stdexcept>

int main(int argc, char** argv) {
    try {
        rtlab::grader::startSandboxedWorker(rtlab::grader::parseSandboxStart(argc, argv));
    } catch (const std::invalid_argument& e) {
        std::cerr << "rtlab-sandbox-start: " << e.what() << "\n";
        return 2;
    }
}
