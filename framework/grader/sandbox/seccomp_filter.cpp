// The fallback's seccomp filter (libseccomp, when raylab was built with it): compiled once in the
// grader, installed by the child with two prctl calls just before exec.
//
// No rule about kill(): the child runs as another user than the grader (root), so the kernel already
// refuses its signals to the grader and to any process not of that user.
#include "grader/sandbox/sandbox_internal.h"

#ifdef RAYLAB_POSIX_SANDBOX

#include "grader/sandbox/unprivileged.h"

#include <cerrno>
#include <cstdio>
#include <stdexcept>
#ifdef __linux__
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#endif
#ifdef RAYLAB_HAVE_SECCOMP
#include <seccomp.h>
#endif

#ifndef __linux__
struct sock_filter {}; // no seccomp: the program stays empty
#endif

namespace raylab::grader::detail {

bool haveSeccomp() {
#ifdef RAYLAB_HAVE_SECCOMP
    return true;
#else
    return false;
#endif
}

#ifdef RAYLAB_HAVE_SECCOMP
namespace {

bool addRules(scmp_filter_ctx filter) {
    // No network: a local socket (AF_UNIX) is all a program of the labs could want. The condition
    // is written out, not with SCMP_A0: its C compound literal is not C++.
    const scmp_arg_cmp domainNotUnix{0, SCMP_CMP_NE, AF_UNIX, 0};
    for (const int call : {SCMP_SYS(socket), SCMP_SYS(socketpair)})
        if (seccomp_rule_add(filter, SCMP_ACT_ERRNO(EAFNOSUPPORT), call, 1, domainNotUnix) != 0)
            return false;
    // No reading or writing another process (another agent of the same user): ptrace, process_vm_*;
    // io_uring would open sockets without the socket call.
    for (const int call : {SCMP_SYS(ptrace), SCMP_SYS(process_vm_readv), SCMP_SYS(process_vm_writev),
                           SCMP_SYS(io_uring_setup), SCMP_SYS(io_uring_enter), SCMP_SYS(io_uring_register)})
        if (seccomp_rule_add(filter, SCMP_ACT_ERRNO(EPERM), call, 0) != 0) return false;
    return true;
}

// libseccomp writes its program to a file descriptor: read back from a temporary file.
std::vector<sock_filter> compile() {
    std::vector<sock_filter> program;
    const scmp_filter_ctx filter = seccomp_init(SCMP_ACT_ALLOW); // a system call of another ABI: killed
    std::FILE* file = std::tmpfile();
    bool done = filter && file && addRules(filter) && seccomp_export_bpf(filter, fileno(file)) == 0;
    if (done) {
        std::rewind(file);
        for (sock_filter instruction; std::fread(&instruction, sizeof instruction, 1, file) == 1;)
            program.push_back(instruction);
        done = !program.empty() && std::ferror(file) == 0;
    }
    if (file) std::fclose(file);
    if (filter) seccomp_release(filter);
    if (!done) throw std::runtime_error("grader: libseccomp cannot compile the sandbox's seccomp filter");
    return program;
}

} // namespace
#endif

const std::vector<sock_filter>& seccompProgram() {
#ifdef RAYLAB_HAVE_SECCOMP
    static const std::vector<sock_filter> program = compile();
#else
    static const std::vector<sock_filter> program;
#endif
    return program;
}

bool installSeccomp(const std::vector<sock_filter>& program) {
    if (program.empty()) return true;
#ifdef __linux__
    sock_fprog filter{static_cast<unsigned short>(program.size()), const_cast<sock_filter*>(program.data())};
    return prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) == 0 && prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, &filter) == 0;
#else
    return false;
#endif
}

} // namespace raylab::grader::detail

#endif
