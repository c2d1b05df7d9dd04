// The worker's first instruction (docs/grading.md, "Isolation and trust"). The worker is linked
// statically with -Wl,-e,rtlab_worker_entry, so the kernel starts it here: before the C
// runtime, before IFUNC resolvers, preinit, init and constructor arrays of any priority, and
// before any symbol a student defines (write, operator new, memcpy ...) could be called.
//
// Here: read the seccomp program the grader built (fd kFilterFd), forbid new privileges,
// install the SIGSYS reporter and load the filter, all with raw system calls and no library
// function, then hand over to the C runtime's _start. If anything fails the worker ends with
// kExitSandboxFailed and no student code has run.
//
// Built with -fno-stack-protector (see grader/CMakeLists.txt): the stack guard lives in
// thread-local storage, which the C runtime has not set up yet.
#include "grader/wire/worker_protocol.h"

#include <asm/unistd.h>
#include <csignal>
#include <cstdint>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <sys/prctl.h>

// The phase the worker is in, for the SIGSYS reporter; worker_main.cpp sets it.
extern "C" {
volatile uint32_t rtlab_worker_phase = 0;
}

namespace {

using rtlab::grader::worker::kExitForbidden;
using rtlab::grader::worker::kExitSandboxFailed;
using rtlab::grader::worker::kFilterFd;
using rtlab::grader::worker::kRecordHeaderSize;
using rtlab::grader::worker::kResultFd;
using rtlab::grader::worker::RecordKind;

long rawSyscall(long number, long a = 0, long b = 0, long c = 0, long d = 0, long e = 0) {
    long result;
    register long r10 asm("r10") = d;
    register long r8 asm("r8") = e;
    asm volatile("syscall" : "=a"(result) : "a"(number), "D"(a), "S"(b), "d"(c), "r"(r10), "r"(r8) : "rcx", "r11", "memory");
    return result;
}

[[noreturn]] void rawExit(int status) {
    for (;;) rawSyscall(__NR_exit_group, status);
}

// The kernel's struct sigaction on x86-64; the restorer is mandatory there.
struct KernelSigaction {
    void (*handler)(int, siginfo_t*, void*);
    unsigned long flags;
    void (*restorer)();
    uint64_t mask;
};

constexpr unsigned long kSaSigInfo = 0x4;
constexpr unsigned long kSaRestorer = 0x04000000;
constexpr int kMaxInstructions = BPF_MAXINSNS;

sock_filter filterProgram[kMaxInstructions];

// Reports which call was refused, in the record format of worker_protocol.h, then ends the
// process: a denied call never returns to student code.
void onForbiddenSystemCall(int, siginfo_t* info, void*) {
    uint8_t record[kRecordHeaderSize + 4];
    uint32_t phase = rtlab_worker_phase;
    uint64_t size = 4;
    auto number = static_cast<uint32_t>(info->si_syscall);
    record[0] = static_cast<uint8_t>(RecordKind::Forbidden);
    for (int i = 0; i < 4; ++i) record[1 + i] = static_cast<uint8_t>(phase >> (8 * i));
    for (int i = 0; i < 8; ++i) record[5 + i] = static_cast<uint8_t>(size >> (8 * i));
    for (int i = 0; i < 4; ++i) record[13 + i] = static_cast<uint8_t>(number >> (8 * i));
    rawSyscall(__NR_write, kResultFd, reinterpret_cast<long>(record), sizeof record);
    rawExit(kExitForbidden);
}

}  // namespace

extern "C" void rtlab_worker_sigreturn();

// Called once from rtlab_worker_entry on the kernel's initial stack, realigned.
extern "C" __attribute__((visibility("hidden"), used)) void rtlab_worker_install_sandbox() {
    // The program arrives as raw sock_filter instructions; a short read ends at end of file.
    auto* bytes = reinterpret_cast<char*>(filterProgram);
    long total = 0;
    while (total < long(sizeof filterProgram)) {
        long n = rawSyscall(__NR_read, kFilterFd, reinterpret_cast<long>(bytes + total), long(sizeof filterProgram) - total);
        if (n < 0) rawExit(kExitSandboxFailed);
        if (n == 0) break;
        total += n;
    }
    if (total == 0 || total % long(sizeof(sock_filter)) != 0) rawExit(kExitSandboxFailed);
    rawSyscall(__NR_close, kFilterFd);

    if (rawSyscall(__NR_prctl, PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) rawExit(kExitSandboxFailed);
    KernelSigaction action{onForbiddenSystemCall, kSaSigInfo | kSaRestorer, rtlab_worker_sigreturn, 0};
    if (rawSyscall(__NR_rt_sigaction, SIGSYS, reinterpret_cast<long>(&action), 0, sizeof(uint64_t)) != 0)
        rawExit(kExitSandboxFailed);
    sock_fprog program{static_cast<unsigned short>(total / long(sizeof(sock_filter))), filterProgram};
    if (rawSyscall(__NR_seccomp, SECCOMP_SET_MODE_FILTER, 0, reinterpret_cast<long>(&program)) != 0)
        rawExit(kExitSandboxFailed);
}

// The entry point keeps the kernel's stack pointer (argc, argv, envp, auxv sit above it) in a
// callee-saved register around the call, and clears rdx, where _start expects the dynamic
// linker's exit hook (none in a static program).
asm(R"(
    .text
    .globl rtlab_worker_entry
    .type rtlab_worker_entry, @function
rtlab_worker_entry:
    mov %rsp, %rbx
    and $-16, %rsp
    call rtlab_worker_install_sandbox
    mov %rbx, %rsp
    xor %edx, %edx
    jmp _start
    .size rtlab_worker_entry, . - rtlab_worker_entry

    .globl rtlab_worker_sigreturn
    .hidden rtlab_worker_sigreturn
    .type rtlab_worker_sigreturn, @function
rtlab_worker_sigreturn:
    mov $15, %eax
    syscall
    .size rtlab_worker_sigreturn, . - rtlab_worker_sigreturn
)");
