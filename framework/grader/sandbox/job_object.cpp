#include "grader/sandbox/job_object.h"

#include "grader/sandbox/process.h"

#include <windows.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <stdexcept>

namespace raylab::grader::detail {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

Clock::duration seconds(double s) {
    return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}

// A handle closed when it goes.
struct Handle {
    HANDLE h = nullptr;
    explicit Handle(HANDLE handle) : h(handle == INVALID_HANDLE_VALUE ? nullptr : handle) {}
    ~Handle() {
        if (h) CloseHandle(h);
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
};

// A file the child inherits as its stdout or stderr (or stdin, from the null device).
HANDLE inheritable(const fs::path& file, DWORD access, DWORD disposition) {
    SECURITY_ATTRIBUTES inherit{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
    return CreateFileW(file.wstring().c_str(), access, FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE, &inherit,
                       disposition, FILE_ATTRIBUTE_NORMAL, nullptr);
}

std::uintmax_t sizeOf(const fs::path& file) {
    std::error_code error;
    const std::uintmax_t size = fs::file_size(file, error);
    return error ? 0 : size;
}

// The job's limits: its processes' memory and CPU time, and death of every process in it once the
// last handle to the job (the grader's) closes.
HANDLE limitedJob(const SandboxLimits& limits) {
    HANDLE job = CreateJobObjectW(nullptr, nullptr);
    if (!job)
        throw std::runtime_error("grader: cannot create a job object (error " + std::to_string(GetLastError()) + ")");
    JOBOBJECT_EXTENDED_LIMIT_INFORMATION info{};
    info.BasicLimitInformation.LimitFlags = JOB_OBJECT_LIMIT_KILL_ON_JOB_CLOSE | JOB_OBJECT_LIMIT_PROCESS_MEMORY |
                                            JOB_OBJECT_LIMIT_JOB_TIME | JOB_OBJECT_LIMIT_DIE_ON_UNHANDLED_EXCEPTION;
    info.BasicLimitInformation.PerJobUserTimeLimit.QuadPart = LONGLONG(limits.cpuSeconds) * 10'000'000; // 100 ns units
    info.ProcessMemoryLimit = SIZE_T(limits.memoryBytes);
    if (!SetInformationJobObject(job, JobObjectExtendedLimitInformation, &info, sizeof info)) {
        CloseHandle(job);
        throw std::runtime_error("grader: cannot set a job object's limits (error " + std::to_string(GetLastError()) +
                                 ")");
    }
    return job;
}

// The job's user time so far has reached its limit (Windows then ends its processes).
bool cpuTimeUsedUp(HANDLE job, const SandboxLimits& limits) {
    JOBOBJECT_BASIC_ACCOUNTING_INFORMATION used{};
    if (!QueryInformationJobObject(job, JobObjectBasicAccountingInformation, &used, sizeof used, nullptr)) return false;
    return used.TotalUserTime.QuadPart >= LONGLONG(limits.cpuSeconds) * 10'000'000;
}

} // namespace

AgentRun runInJob(const AgentCommand& c, const SandboxLimits& limits) {
    const fs::path results = c.scratch / "results.jsonl", requestFile = c.scratch / "requests.jsonl";
    fs::remove(results);
    if (!(std::ofstream(requestFile, std::ios::binary) << c.requests))
        throw std::runtime_error("grader: cannot write " + requestFile.string());
    std::vector<std::string> argv{c.program.string()};
    argv.insert(argv.end(), c.args.begin(), c.args.end());
    argv.insert(argv.end(), {"--request-file", requestFile.string(), "--report-file", results.string()});
    std::wstring commandLine = windowsCommandLine(argv);

    const Handle job(limitedJob(limits));
    const fs::path outputs[] = {c.scratch / "stdout.txt", c.scratch / "stderr.txt"};
    const Handle in(inheritable("NUL", GENERIC_READ, OPEN_EXISTING));
    const Handle out(inheritable(outputs[0], GENERIC_WRITE, CREATE_ALWAYS));
    const Handle err(inheritable(outputs[1], GENERIC_WRITE, CREATE_ALWAYS));
    if (!in.h || !out.h || !err.h)
        throw std::runtime_error("grader: cannot open the agent's output files in " + c.scratch.string());
    STARTUPINFOW startup{};
    startup.cb = sizeof startup;
    startup.dwFlags = STARTF_USESTDHANDLES;
    startup.hStdInput = in.h;
    startup.hStdOutput = out.h;
    startup.hStdError = err.h;
    // A crash ends the agent at once: no error box waits for a click (the agent inherits this mode).
    SetErrorMode(SEM_FAILCRITICALERRORS | SEM_NOGPFAULTERRORBOX);
    PROCESS_INFORMATION process{};
    // Suspended until it is in the job: not one instruction runs unlimited.
    if (!CreateProcessW(nullptr, commandLine.data(), nullptr, nullptr, TRUE, CREATE_SUSPENDED | CREATE_NO_WINDOW,
                        nullptr, c.scratch.wstring().c_str(), &startup, &process))
        throw std::runtime_error("grader: cannot start " + c.program.string() + " (error " +
                                 std::to_string(GetLastError()) + ")");
    const Handle child(process.hProcess), thread(process.hThread);
    if (!AssignProcessToJobObject(job.h, child.h)) {
        TerminateProcess(child.h, 1);
        throw std::runtime_error("grader: cannot put " + c.program.string() + " in a job object (error " +
                                 std::to_string(GetLastError()) + ")");
    }
    ResumeThread(thread.h);

    AgentRun run;
    const Clock::time_point end = Clock::now() + seconds(limits.totalSeconds);
    Clock::time_point deadline = std::min(end, Clock::now() + seconds(limits.wallSeconds));
    std::uintmax_t answered = 0;
    // Short naps: an answer restarts the item's clock within 20 ms.
    while (WaitForSingleObject(child.h, 20) == WAIT_TIMEOUT) {
        const std::uintmax_t size = sizeOf(results);
        if (size != answered) { // it spoke: a new item's time
            answered = size;
            deadline = std::min(end, Clock::now() + seconds(limits.wallSeconds));
        }
        if (size + sizeOf(outputs[0]) + sizeOf(outputs[1]) > limits.fileBytes) {
            run.outputLimit = true;
            break;
        }
        if (Clock::now() >= deadline) {
            run.timedOut = true;
            break;
        }
    }
    // The agent and whatever it started, at once.
    TerminateJobObject(job.h, 1);
    WaitForSingleObject(child.h, INFINITE);
    if (!run.timedOut && !run.outputLimit) {
        DWORD code = 0;
        GetExitCodeProcess(child.h, &code);
        run.exitCode = int(code);
        run.cpuLimit = cpuTimeUsedUp(job.h, limits);
    }
    return run;
}

} // namespace raylab::grader::detail
