#include "grader/engine/system_call_filter.h"

#include <seccomp.h>

#include <cerrno>
#include <cstdlib>
#include <csignal>
#include <sched.h>
#include <stdexcept>
#include <string>
#include <sys/ioctl.h>
#include <unistd.h>
#include <fcntl.h>
#include <sys/mman.h>

namespace rtlab::grader {
namespace {

class Filter {
public:
    Filter() : context_(seccomp_init(SCMP_ACT_TRAP)) {
        if (!context_) throw std::runtime_error("seccomp_init failed");
    }
    ~Filter() { seccomp_release(context_); }
    Filter(const Filter&) = delete;
    Filter& operator=(const Filter&) = delete;

    void allow(int call) { add(SCMP_ACT_ALLOW, call, {}); }
    void allowIf(int call, scmp_arg_cmp condition) { add(SCMP_ACT_ALLOW, call, {condition}); }
    void fail(int call, int error) { add(SCMP_ACT_ERRNO(error), call, {}); }
    int exportToMemoryFile() {
        int fd = memfd_create("rtlab-seccomp", MFD_CLOEXEC);
        if (fd < 0) throw std::runtime_error("memfd_create failed");
        if (seccomp_export_bpf(context_, fd) != 0 || lseek(fd, 0, SEEK_SET) != 0) {
            close(fd);
            throw std::runtime_error("seccomp_export_bpf failed");
        }
        return fd;
    }

private:
    void add(uint32_t action, int call, std::initializer_list<scmp_arg_cmp> conditions) {
        int rc = seccomp_rule_add_array(context_, action, call, static_cast<unsigned>(conditions.size()),
                                        conditions.size() ? conditions.begin() : nullptr);
        if (rc != 0) throw std::runtime_error("seccomp_rule_add failed for system call " + std::to_string(call));
    }
    scmp_filter_ctx context_;
};

}  // namespace

int exportSystemCallFilter(int resultFd, int workerPid) {
    Filter filter;
    // Memory, time, threads' synchronisation and ending the process.
    for (int call : {SCMP_SYS(brk), SCMP_SYS(mmap), SCMP_SYS(munmap), SCMP_SYS(mremap), SCMP_SYS(mprotect),
                     SCMP_SYS(madvise), SCMP_SYS(futex), SCMP_SYS(set_robust_list), SCMP_SYS(rseq),
                     SCMP_SYS(sched_yield), SCMP_SYS(sched_getaffinity), SCMP_SYS(getpid), SCMP_SYS(gettid),
                     SCMP_SYS(clock_gettime), SCMP_SYS(clock_getres), SCMP_SYS(gettimeofday), SCMP_SYS(time),
                     SCMP_SYS(nanosleep), SCMP_SYS(clock_nanosleep), SCMP_SYS(getrandom),
                     SCMP_SYS(rt_sigreturn), SCMP_SYS(rt_sigprocmask), SCMP_SYS(sigaltstack),
                     SCMP_SYS(exit), SCMP_SYS(exit_group), SCMP_SYS(read), SCMP_SYS(close), SCMP_SYS(fstat),
                     // the C runtime's start-up in a static program: thread pointer, thread id
                     SCMP_SYS(arch_prctl), SCMP_SYS(set_tid_address)})
        filter.allow(call);
    // Start-up looks for its own file name ($ORIGIN); there is nothing to find.
    filter.fail(SCMP_SYS(readlink), ENOENT);
    filter.fail(SCMP_SYS(readlinkat), ENOENT);
    // Writing: only the output capture (stdout, stderr) and the result pipe.
    for (int fd : {STDOUT_FILENO, STDERR_FILENO, resultFd}) {
        filter.allowIf(SCMP_SYS(write), SCMP_A0(SCMP_CMP_EQ, static_cast<scmp_datum_t>(fd)));
        filter.allowIf(SCMP_SYS(writev), SCMP_A0(SCMP_CMP_EQ, static_cast<scmp_datum_t>(fd)));
    }
    // glibc's fstat(fd) is newfstatat(fd, "", buf, AT_EMPTY_PATH).
    filter.allowIf(SCMP_SYS(newfstatat), SCMP_A3(SCMP_CMP_MASKED_EQ, AT_EMPTY_PATH, AT_EMPTY_PATH));
    // Threads of this process (std::thread), never a new process: clone needs CLONE_THREAD,
    // and clone3, whose flags a filter cannot see, reports "not supported" so glibc falls
    // back to clone.
    filter.allowIf(SCMP_SYS(clone), SCMP_A0(SCMP_CMP_MASKED_EQ, CLONE_THREAD, CLONE_THREAD));
    filter.fail(SCMP_SYS(clone3), ENOSYS);
    // Signals to itself only (abort() raises SIGABRT), and no handler that could hide SIGSYS.
    auto self = static_cast<scmp_datum_t>(workerPid);
    filter.allowIf(SCMP_SYS(kill), SCMP_A0(SCMP_CMP_EQ, self));
    filter.allowIf(SCMP_SYS(tgkill), SCMP_A0(SCMP_CMP_EQ, self));
    filter.allowIf(SCMP_SYS(rt_sigaction), SCMP_A0(SCMP_CMP_NE, SIGSYS));
    // Reading limits is fine, raising them is not.
    filter.allowIf(SCMP_SYS(prlimit64), SCMP_A2(SCMP_CMP_EQ, 0));
    // isatty() on the output capture.
    filter.fail(SCMP_SYS(ioctl), ENOTTY);
    return filter.exportToMemoryFile();
}

std::string systemCallName(int number) {
    char* name = seccomp_syscall_resolve_num_arch(SCMP_ARCH_NATIVE, number);
    if (!name) return "system call " + std::to_string(number);
    std::string result = name;
    free(name);
    return result;
}

}  // namespace rtlab::grader
