// The worker's main: runs in the sandbox the entry point installed (sandbox_entry.cpp), reads
// one phase at a time from the grader, runs its task and reports how it ended
// (worker_protocol.h). Nothing here is trusted by the grader: a student can replace any of
// it, and all it could gain is results the grader validates anyway.
#include "framework/core/error.h"
#include "grader/wire/worker_protocol.h"
#include "grader/worker/worker_tasks.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <malloc.h>
#include <memory>
#include <new>
#include <span>
#include <string>
#include <sys/mman.h>
#include <unistd.h>

extern "C" volatile uint32_t rtlab_worker_phase;

namespace rtlab::grader::worker {
namespace {

void writeAll(int fd, const void* data, size_t size) {
    const auto* p = static_cast<const uint8_t*>(data);
    while (size > 0) {
        ssize_t n = write(fd, p, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) _exit(kExitBadRequest);
        p += n;
        size -= static_cast<size_t>(n);
    }
}

void sendRecord(RecordKind kind, uint32_t phase, const void* payload, uint64_t size) {
    uint8_t header[kRecordHeaderSize];
    header[0] = static_cast<uint8_t>(kind);
    std::memcpy(header + 1, &phase, 4);
    std::memcpy(header + 5, &size, 8);
    writeAll(kResultFd, header, sizeof header);
    if (size > 0) writeAll(kResultFd, payload, size);
}

void sendText(RecordKind kind, uint32_t phase, const std::string& text) { sendRecord(kind, phase, text.data(), text.size()); }

// False at the end of the input.
bool readExactly(void* data, size_t size) {
    auto* p = static_cast<uint8_t*>(data);
    while (size > 0) {
        ssize_t n = read(STDIN_FILENO, p, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        p += n;
        size -= static_cast<size_t>(n);
    }
    return true;
}

template <typename T>
T readValue() {
    T value;
    if (!readExactly(&value, sizeof value)) _exit(kExitBadRequest);
    return value;
}

// The heap a phase's input and the task's decoded copy of it take, faulted in by the kernel in
// one call rather than one page at a time: on a virtual machine each first touch of a page
// costs about 10 us, a large part of what a test whose stub is not started cost when its
// phase carried megabytes. Blocks below glibc's largest mmap threshold come from the heap,
// which keeps what is freed, so the input and its copy land in the populated block.
constexpr size_t kLargestHeapBlock = size_t(32) << 20;

void configureHeap() {
    mallopt(M_MMAP_THRESHOLD, int(kLargestHeapBlock));
    mallopt(M_TRIM_THRESHOLD, int(kLargestHeapBlock));
}

void prefaultHeap(size_t bytes) {
    if (bytes == 0 || bytes >= kLargestHeapBlock) return;
    auto* block = static_cast<uint8_t*>(std::malloc(bytes));
    if (!block) return;
    const auto page = uintptr_t(sysconf(_SC_PAGESIZE));
    uintptr_t first = (uintptr_t(block) + page - 1) & ~(page - 1), last = (uintptr_t(block) + bytes) & ~(page - 1);
    if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_POPULATE_WRITE);
    std::free(block);
}

void runPhase(uint32_t phase, Task task, std::span<const uint8_t> input, WorkerState& state) {
    rtlab_worker_phase = phase;
    sendRecord(RecordKind::PhaseStart, phase, nullptr, 0);
    try {
        ByteReader in(input);
        ByteWriter out;
        task(in, out, state);
        sendRecord(RecordKind::PhaseData, phase, out.bytes().data(), out.bytes().size());
    } catch (const NotImplemented& e) {
        sendText(RecordKind::NotStarted, phase, e.stub);
    } catch (const PhaseNotRun& e) {
        sendText(RecordKind::NotRun, phase, e.what());
    } catch (const std::bad_alloc&) {
        sendRecord(RecordKind::OutOfMemory, phase, nullptr, 0);
    } catch (const std::exception& e) {
        sendText(RecordKind::Failed, phase, std::string("threw an exception: ") + e.what());
    } catch (...) {
        sendText(RecordKind::Failed, phase, "threw an exception that is not a std::exception");
    }
}

}  // namespace
}  // namespace rtlab::grader::worker

int main() {
    using namespace rtlab::grader::worker;
    // Registered after every handler a student's initialisers may have registered, so it runs
    // first when student code calls exit(), and the grader learns that it did.
    std::atexit([] { _exit(kExitCalled); });
    configureHeap();
    WorkerState state;
    while (true) {
        auto phase = readValue<uint32_t>();
        if (phase == kEndOfRequest) break;
        auto nameLength = readValue<uint32_t>();
        if (nameLength > kMaxTaskName) _exit(kExitBadRequest);
        std::string name(nameLength, '\0');
        if (!readExactly(name.data(), nameLength)) _exit(kExitBadRequest);
        auto inputLength = readValue<uint64_t>();
        prefaultHeap(2 * inputLength);
        auto input = std::make_unique_for_overwrite<uint8_t[]>(inputLength);
        if (!readExactly(input.get(), inputLength)) _exit(kExitBadRequest);
        Task task = findTask(name);
        if (!task) _exit(kExitBadRequest);
        runPhase(phase, task, {input.get(), inputLength}, state);
    }
    sendRecord(RecordKind::Done, 0, nullptr, 0);
    _exit(0);
}
