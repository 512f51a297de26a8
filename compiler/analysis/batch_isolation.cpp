#include "analysis/batch_isolation.hpp"

#include "analysis/batch_files.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <iostream>
#include <poll.h>
#include <sstream>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace yamsc::analysis {

namespace {

using Clock = std::chrono::steady_clock;

/// A child's report: "ok wall_s final_size message_size\n" then both texts.
std::string report_of(const CaseSummary& s) {
    std::ostringstream out;
    out.precision(17);
    out << (s.ok ? 1 : 0) << ' ' << s.wall_s << ' ' << s.final.size() << ' ' << s.message.size()
        << '\n'
        << s.final << s.message;
    return out.str();
}

/// Reads a complete report into `s`; false when it was cut short.
bool read_report(const std::string& text, CaseSummary& s) {
    std::istringstream in(text);
    int ok = 0;
    std::size_t final_size = 0, message_size = 0;
    if (!(in >> ok >> s.wall_s >> final_size >> message_size) || in.get() != '\n') return false;
    const std::size_t at = static_cast<std::size_t>(in.tellg());
    if (text.size() != at + final_size + message_size) return false;
    s.ok = ok == 1;
    s.final = text.substr(at, final_size);
    s.message = text.substr(at + final_size);
    return true;
}

void write_all(int fd, const std::string& text) {
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;
        done += static_cast<std::size_t>(n);
    }
}

struct Child {
    Job* job = nullptr;
    pid_t pid = -1;
    int fd = -1;
    std::string report;
    Clock::time_point start, deadline;
    double limit = 0;
    bool timed_out = false;
};

/// The child's side: runs the case and reports; never returns.
[[noreturn]] void run_child(Job& job, pid_t parent, int fd,
                            const std::function<void(Job&, Loaded&)>& run) {
    // Dies with the batch (a kill -9 of it leaves no case running on).
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);
    // A controller's chatter goes to stderr: stdout is the batch's result line.
    ::dup2(STDERR_FILENO, STDOUT_FILENO);
    try {
        // This process's copy of the batch's memory is its own: the case binds
        // its parameters in the loaded model itself, with no copy of it.
        run(job, const_cast<Loaded&>(*job.model));
    } catch (const std::exception& e) {
        job.summary.ok = false;
        job.summary.message = e.what();
    } catch (...) {
        job.summary.ok = false;
        job.summary.message = "an exception that is not a std::exception";
    }
    std::cout.flush();
    std::fflush(nullptr);
    write_all(fd, report_of(job.summary));
    ::_exit(0); // no exit handlers: they are the batch's, not this case's
}

Child start(Job& job, double default_limit, const std::function<void(Job&, Loaded&)>& run) {
    // Nothing buffered may be written twice, by the batch and by the child.
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0)
        throw std::runtime_error(std::string("cannot create a pipe for the case: ") +
                                 std::strerror(errno));
    Child c;
    c.job = &job;
    c.start = Clock::now();
    c.limit = job.c->time_limit > 0 ? job.c->time_limit : default_limit;
    c.deadline = c.start + std::chrono::duration_cast<Clock::duration>(
                               std::chrono::duration<double>(c.limit > 0 ? c.limit : 1e9));
    const pid_t parent = ::getpid();
    c.pid = ::fork();
    if (c.pid < 0) {
        const int error = errno;
        ::close(fds[0]);
        ::close(fds[1]);
        throw std::runtime_error(std::string("cannot start a process for the case: ") +
                                 std::strerror(error));
    }
    if (c.pid == 0) {
        ::close(fds[0]);
        run_child(job, parent, fds[1], run);
    }
    ::close(fds[1]);
    c.fd = fds[0];
    return c;
}

std::string number_text(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

/// The job's summary once its child has ended with `status`.
void conclude(Child& c, int status, const std::string& dir) {
    Job& job = *c.job;
    CaseSummary s;
    const bool reported = read_report(c.report, s);
    if (reported && !c.timed_out && WIFEXITED(status) && WEXITSTATUS(status) == 0) {
        job.summary.ok = s.ok;
        job.summary.final = s.final;
        job.summary.message = s.message;
        job.summary.wall_s = s.wall_s;
        return;
    }
    std::string reason;
    if (c.timed_out)
        reason = "time limit of " + number_text(c.limit) + " s exceeded";
    else if (WIFSIGNALED(status))
        reason = "killed by " + signal_name(WTERMSIG(status)) +
                 " (a crash in the case: its controller, a user function or the model)";
    else
        reason = "the case's process exited with status " + std::to_string(WEXITSTATUS(status)) +
                 " before it finished (exit() called by its controller or a user function)";
    job.summary.ok = false;
    job.summary.final.clear();
    job.summary.message = job.c->row_at + ": error: " + reason;
    job.summary.wall_s = std::chrono::duration<double>(Clock::now() - c.start).count();
    // A case stopped while writing leaves neither a part of its result nor a
    // record of it.
    forget(dir, job.c->id);
    remove_leftovers(dir, {job.c->id});
}

/// Reads what `c` wrote; true when its pipe is closed (the child has ended).
bool drain(Child& c) {
    char buf[4096];
    while (true) {
        const ssize_t n = ::read(c.fd, buf, sizeof buf);
        if (n > 0) {
            c.report.append(buf, static_cast<std::size_t>(n));
            if (static_cast<std::size_t>(n) < sizeof buf) return false;
            continue;
        }
        if (n < 0 && errno == EINTR) continue;
        return n == 0 || errno != EAGAIN;
    }
}

} // namespace

std::string signal_name(int signal) {
    static const std::pair<int, const char*> names[] = {
        {SIGSEGV, "SIGSEGV"}, {SIGBUS, "SIGBUS"},   {SIGFPE, "SIGFPE"},   {SIGILL, "SIGILL"},
        {SIGABRT, "SIGABRT"}, {SIGKILL, "SIGKILL"}, {SIGTERM, "SIGTERM"}, {SIGINT, "SIGINT"},
        {SIGPIPE, "SIGPIPE"}, {SIGTRAP, "SIGTRAP"}, {SIGSYS, "SIGSYS"},   {SIGXCPU, "SIGXCPU"},
        {SIGXFSZ, "SIGXFSZ"}, {SIGHUP, "SIGHUP"},   {SIGQUIT, "SIGQUIT"}, {SIGALRM, "SIGALRM"},
        {SIGUSR1, "SIGUSR1"}, {SIGUSR2, "SIGUSR2"}};
    for (const auto& [number, name] : names)
        if (number == signal) return name;
    return "signal " + std::to_string(signal);
}

void run_isolated(const std::vector<Job*>& jobs, std::size_t at_once, double default_limit,
                  const std::string& dir, const StopOnSignal& stop,
                  const std::function<void(Job&, Loaded&)>& run,
                  const std::function<void(const Job&)>& finished) {
    std::size_t next = 0;
    std::vector<Child> running;
    while (true) {
        while (running.size() < at_once && next < jobs.size() && !stop.stopped()) {
            Job& job = *jobs[next++];
            try {
                running.push_back(start(job, default_limit, run));
            } catch (const std::exception& e) {
                // No process (too many, no memory): this case fails, the others may start.
                job.summary.ok = false;
                job.summary.message = job.c->row_at + ": error: " + e.what();
                finished(job);
                continue;
            }
            ::fcntl(running.back().fd, F_SETFL, O_NONBLOCK);
        }
        if (running.empty()) break;
        // Wake for output, the nearest deadline, or at least every 0.2 s to see a stop.
        auto wait = std::chrono::milliseconds(200);
        const auto now = Clock::now();
        for (const Child& c : running)
            if (!c.timed_out)
                wait = std::min(
                    wait, std::chrono::duration_cast<std::chrono::milliseconds>(c.deadline - now) +
                              std::chrono::milliseconds(1));
        std::vector<pollfd> fds;
        for (const Child& c : running) fds.push_back({c.fd, POLLIN, 0});
        ::poll(fds.data(), fds.size(), static_cast<int>(std::max<long>(0, wait.count())));
        for (std::size_t i = 0; i < running.size();) {
            Child& c = running[i];
            if (!c.timed_out && c.limit > 0 && Clock::now() >= c.deadline) {
                ::kill(c.pid, SIGKILL);
                c.timed_out = true;
            }
            if (!drain(c)) {
                ++i;
                continue;
            }
            ::close(c.fd);
            int status = 0;
            while (::waitpid(c.pid, &status, 0) < 0 && errno == EINTR) {
            }
            conclude(c, status, dir);
            finished(*c.job);
            running.erase(running.begin() + static_cast<std::ptrdiff_t>(i));
        }
    }
}

} // namespace yamsc::analysis
