// Outputs never destroy anything. For every file a command writes (compile -o,
// --header, --depfile in C++, C and LaTeX; sim -o and --plot; lin --sweep -o and
// --plot; lin --format openfast-lin -o; sid -o; from-openfast -o): a character
// device (made here with mknod, when the test runs as root) stays a device, a
// FIFO stays a FIFO and its reader gets the content, a symbolic link stays a link and its target
// gets the content. An output that names an input (also through a link, a hard link or another
// spelling) or another output is a usage error that leaves every file as it
// was, and a run that fails leaves the old outputs unchanged.
#include "test_files.hpp"

#include <doctest/doctest.h>

#include <dirent.h>
#include <fcntl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <map>
#include <string>
#include <thread>
#include <vector>

using namespace test_support;

namespace {

const std::string source_dir = YAMSC_SOURCE_DIR;

std::string quoted(const std::string& path) {
    return "'" + path + "'";
}

struct Run {
    int status;
    std::string out, err;
};

/// Runs yamsc in `dir`; its stdout and stderr are kept outside `dir`.
Run yamsc(const std::string& dir, const std::string& args) {
    const std::string log = std::string(YAMSC_TEST_BINARY_DIR) + "/output_safety";
    const int status = exit_status("cd " + quoted(dir) + " && " + YAMSC_EXE + " " + args + " >" +
                                   quoted(log + ".out") + " 2>" + quoted(log + ".err"));
    return {status, read_file(log + ".out"), read_file(log + ".err")};
}

mode_t file_type(const std::string& path) {
    struct stat st {};
    return ::lstat(path.c_str(), &st) == 0 ? (st.st_mode & S_IFMT) : 0;
}

std::string link_text(const std::string& path) {
    char buffer[4096];
    const ssize_t n = ::readlink(path.c_str(), buffer, sizeof buffer);
    return n < 0 ? "" : std::string(buffer, static_cast<std::size_t>(n));
}

std::string replace_out(const std::string& args, const std::string& path) {
    return replace_all(args, "{OUT}", quoted(path));
}

/// A flexible mast under gravity `g` (a parameter, for --sweep), its SID beside it.
const char* mast_model = "model mast \"A clamped flexible mast\"\n"
                         "param g = 9.81\n"
                         "gravity (0, 0, -g)\n"
                         "dof q1\n"
                         "flexible mast { sid = \"mast.sid\"; modes = (q1) }\n"
                         "joint ground -> mast\n";

/// The inputs every case reads, under `root/in`: the mast model and its SID, a
/// model with an error, and an ElastoDyn deck with its tower and blade files.
void write_inputs(const std::string& root) {
    const std::string in = root + "/in";
    std::filesystem::create_directories(in);
    write_file(in + "/model.mbd", mast_model);
    write_file(in + "/mast.sid", read_file(source_dir + "/tests/sid/data/minimal.sid"));
    write_file(in + "/broken.mbd", "model broken\ndof q1\nrigid b {\n");
    for (const char* name :
         {"NREL5MW_ED_Onshore.dat", "NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat",
          "NRELOffshrBsline5MW_Blade.dat"})
        write_file(in + "/" + name, read_file(source_dir + "/models/data/" + name));
}

/// Every input file under `root/in` with its bytes.
std::map<std::string, std::string> snapshot(const std::string& root) {
    std::map<std::string, std::string> files;
    for (const auto& e : std::filesystem::directory_iterator(root + "/in"))
        files[e.path().string()] = read_file(e.path().string());
    return files;
}

/// One output of one command: `args` (run in the case's folder) with `{OUT}`
/// where the output goes; `file` is the output's name in every sub-folder, so
/// that contents that depend on the name (from-openfast's model) agree.
struct Output {
    const char* what;
    std::string args;
    std::string file;
};

const std::string sim = "sim in/model.mbd --tmax 0.05 --dt 0.01";
const std::string sweep = "lin in/model.mbd --sweep g=0:5:10";
const std::string tower = "in/NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat";

const std::vector<Output> outputs{
    {"compile -o (C++)", "in/model.mbd -o {OUT} --header other/m.hpp", "m.cpp"},
    {"compile --header (C++)", "in/model.mbd -o other/m.cpp --header {OUT}", "m.hpp"},
    {"compile -o (C)", "in/model.mbd -o {OUT} --header other/m.h", "m.c"},
    {"compile --header (C)", "in/model.mbd -o other/m.c --header {OUT}", "m.h"},
    {"compile -o (LaTeX)", "in/model.mbd --lang latex -o {OUT}", "m.tex"},
    {"compile --depfile", "in/model.mbd -o other/m.cpp --depfile {OUT}", "m.d"},
    {"sim -o", sim + " -o {OUT}", "out.csv"},
    {"sim --plot", sim + " --plot {OUT}", "out.svg"},
    {"lin --sweep -o", sweep + " -o {OUT}", "sweep.csv"},
    {"lin --sweep --plot", sweep + " --plot {OUT}", "sweep.svg"},
    {"lin --format openfast-lin -o", "lin in/model.mbd --format openfast-lin -o {OUT}", "m.lin"},
    {"sid -o", "sid --elastodyn-tower " + tower + " --length 87.6 -o {OUT}", "tower.sid"},
    {"from-openfast -o", "from-openfast in/NREL5MW_ED_Onshore.dat -o {OUT}", "turbine.mbd"},
};

/// Reads a FIFO to its end in a thread: started before yamsc opens it for writing.
class FifoReader {
public:
    explicit FifoReader(std::string path) : path_(std::move(path)) {
        thread_ = std::thread([this] {
            const int fd = ::open(path_.c_str(), O_RDONLY);
            if (fd < 0) return;
            char buffer[65536];
            for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) != 0;) {
                if (n < 0 && errno == EINTR) continue;
                if (n < 0) break;
                content_.append(buffer, static_cast<std::size_t>(n));
            }
            ::close(fd);
        });
    }
    /// The content read, once the writer is gone. A writer that never opened
    /// the FIFO would leave the reader waiting in open(): a writer opened and
    /// closed here releases it (ENXIO when the reader has already finished).
    std::string finish() {
        const int fd = ::open(path_.c_str(), O_WRONLY | O_NONBLOCK);
        if (fd >= 0) ::close(fd);
        thread_.join();
        return content_;
    }

private:
    std::string path_;
    std::string content_;
    std::thread thread_;
};

/// A character device of our own (the null device's numbers) at `path`, or
/// false when this process may not make one.
bool make_device(const std::string& path) {
    if (::geteuid() != 0) {
        MESSAGE("not root: the character device case is skipped");
        return false;
    }
    if (::mknod(path.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0) {
        MESSAGE("mknod failed (" << std::strerror(errno)
                                 << "): the character device case is skipped");
        return false;
    }
    return true;
}

} // namespace

TEST_CASE("every output to a FIFO, a device or through a symbolic link keeps what is there") {
    const std::string root = scratch_dir("output_safety", "kinds");
    write_inputs(root);
    for (const char* folder : {"other", "ref", "fifo", "dev", "link", "target", "dangling", "new"})
        std::filesystem::create_directories(root + "/" + folder);
    for (const Output& o : outputs) {
        CAPTURE(o.what);
        // The content, written to a regular file.
        const std::string ref = root + "/ref/" + o.file;
        REQUIRE(yamsc(root, replace_out(o.args, "ref/" + o.file)).status == 0);
        const std::string expected = read_file(ref);
        REQUIRE(expected.size() > 20);

        // A FIFO: written in place, read whole by its reader, still a FIFO.
        const std::string fifo = root + "/fifo/" + o.file;
        REQUIRE(::mkfifo(fifo.c_str(), 0666) == 0);
        FifoReader reader(fifo);
        CHECK(yamsc(root, replace_out(o.args, "fifo/" + o.file)).status == 0);
        CHECK(reader.finish() == expected);
        CHECK(file_type(fifo) == S_IFIFO);

        // A character device: written in place, still the same device.
        const std::string device = root + "/dev/" + o.file;
        if (make_device(device)) {
            CHECK(yamsc(root, replace_out(o.args, "dev/" + o.file)).status == 0);
            struct stat st {};
            REQUIRE(::lstat(device.c_str(), &st) == 0);
            CHECK(S_ISCHR(st.st_mode));
            CHECK(st.st_rdev == makedev(1, 3));
        }

        // A symbolic link to a file in another folder: the link stays, the target
        // is replaced (its temporary file in the target's folder).
        const std::string link = root + "/link/" + o.file;
        write_file(root + "/target/" + o.file, "old content\n");
        REQUIRE(::symlink(("../target/" + o.file).c_str(), link.c_str()) == 0);
        CHECK(yamsc(root, replace_out(o.args, "link/" + o.file)).status == 0);
        CHECK(file_type(link) == S_IFLNK);
        CHECK(link_text(link) == "../target/" + o.file);
        CHECK(read_file(root + "/target/" + o.file) == expected);

        // A link to a file not there yet: the file is made where the link points.
        const std::string dangling = root + "/dangling/" + o.file;
        REQUIRE(::symlink(("../new/" + o.file).c_str(), dangling.c_str()) == 0);
        CHECK(yamsc(root, replace_out(o.args, "dangling/" + o.file)).status == 0);
        CHECK(file_type(dangling) == S_IFLNK);
        CHECK(file_type(root + "/new/" + o.file) == S_IFREG);
        CHECK(read_file(root + "/new/" + o.file) == expected);
    }
    for (const char* folder : {"other", "ref", "fifo", "dev", "link", "target", "dangling", "new"})
        CHECK(temporaries(root + "/" + folder).empty());
}

TEST_CASE("an output that is an input is a usage error, and every file stays as it was") {
    const std::string root = scratch_dir("output_safety", "inputs");
    write_inputs(root);
    std::filesystem::create_directories(root + "/out");
    // Other names of the model: a symbolic link, a hard link.
    REQUIRE(::symlink("../in/model.mbd", (root + "/out/link.mbd").c_str()) == 0);
    REQUIRE(::link((root + "/in/model.mbd").c_str(), (root + "/out/hard.mbd").c_str()) == 0);
    // A model with symbolic modes, for --sid, and a reference table for --compare.
    write_file(root + "/in/symbolic.mbd", replace_all(mast_model, "sid = \"mast.sid\"; modes",
                                                      "sid = \"mast.sid\"; symbolic modes"));
    write_file(root + "/in/other.sid", read_file(root + "/in/mast.sid"));
    write_file(root + "/in/ref.csv", "time,q1\n0,0\n1,0\n");
    const auto before = snapshot(root);

    struct Clash {
        std::string args;
        std::string message; ///< names both roles
    };
    const std::string deck = "from-openfast in/NREL5MW_ED_Onshore.dat -o ";
    const std::vector<Clash> clashes{
        {"in/model.mbd -o in/model.mbd --lang cpp",
         "-o 'in/model.mbd' is the model 'in/model.mbd'"},
        {"in/model.mbd -o ./in//model.mbd --lang c", "-o './in//model.mbd' is the model"},
        {"in/model.mbd -o out/a.cpp --header out/link.mbd",
         "--header 'out/link.mbd' is the model 'in/model.mbd'"},
        {"in/model.mbd -o out/hard.mbd --lang latex", "-o 'out/hard.mbd' is the model"},
        {"in/model.mbd -o in/mast.sid --lang cpp",
         "-o 'in/mast.sid' is the model's data file 'in/mast.sid'"},
        {"in/model.mbd -o out/a.cpp --depfile in/mast.sid", "--depfile 'in/mast.sid' is the "
                                                            "model's data file"},
        {sim + " -o in/model.mbd", "-o 'in/model.mbd' is the model"},
        {sim + " --plot in/mast.sid", "--plot 'in/mast.sid' is the model's data file"},
        {sim + " --compare in/ref.csv --plot in/ref.csv",
         "--plot 'in/ref.csv' is the --compare table 'in/ref.csv'"},
        {"sim in/symbolic.mbd --tmax 0.05 --dt 0.01 --sid mast=in/other.sid -o in/other.sid",
         "-o 'in/other.sid' is the --sid file of body mast 'in/other.sid'"},
        {sweep + " -o out/link.mbd", "-o 'out/link.mbd' is the model"},
        {sweep + " -o out/s.csv --plot in/mast.sid", "--plot 'in/mast.sid' is the model's data"},
        {"lin in/symbolic.mbd --sweep g=0:5:10 --sid mast=in/other.sid -o in/other.sid",
         "-o 'in/other.sid' is the --sid file of body mast"},
        {"lin in/model.mbd --format openfast-lin -o in/mast.sid",
         "-o 'in/mast.sid' is the model's data file"},
        {"sid --elastodyn-tower " + tower + " --length 87.6 -o " + tower,
         "-o '" + tower + "' is --elastodyn-tower '" + tower + "'"},
        {deck + "in/NREL5MW_ED_Onshore.dat", "-o 'in/NREL5MW_ED_Onshore.dat' is the deck"},
        {deck + tower, "-o '" + tower + "' is the tower file of the deck"},
        {deck + "in/NRELOffshrBsline5MW_Blade.dat",
         "-o 'in/NRELOffshrBsline5MW_Blade.dat' is a blade file of the deck"},
    };
    for (const Clash& c : clashes) {
        CAPTURE(c.args);
        const Run run = yamsc(root, c.args);
        CHECK(run.status == 2);
        CHECK(run.err.find("usage error: " + c.message) != std::string::npos);
        CHECK(run.err.find("an output must not replace an input (nothing was written)") !=
              std::string::npos);
        CHECK(snapshot(root) == before);
        CHECK(temporaries(root + "/in").empty());
        // No other output of the run was written either.
        CHECK_FALSE(std::filesystem::exists(root + "/out/a.cpp"));
        CHECK_FALSE(std::filesystem::exists(root + "/out/s.csv"));
    }
    CHECK(file_type(root + "/out/link.mbd") == S_IFLNK);
}

TEST_CASE("two outputs of one run that are the same file are a usage error") {
    const std::string root = scratch_dir("output_safety", "twice");
    write_inputs(root);
    write_file(root + "/old.txt", "old\n");
    REQUIRE(::symlink("old.txt", (root + "/alias.txt").c_str()) == 0);
    const std::vector<std::pair<std::string, std::string>> clashes{
        {"in/model.mbd -o m.cpp --header m.cpp", "-o 'm.cpp' and --header 'm.cpp'"},
        {"in/model.mbd -o m.cpp --header ./m.cpp", "-o 'm.cpp' and --header './m.cpp'"},
        {"in/model.mbd -o m.cpp --depfile m.cpp", "-o 'm.cpp' and --depfile 'm.cpp'"},
        {"in/model.mbd -o m.cpp --header m.hpp --depfile m.hpp",
         "--header 'm.hpp' and --depfile 'm.hpp'"},
        {"in/model.mbd --lang latex -o old.txt --depfile alias.txt",
         "-o 'old.txt' and --depfile 'alias.txt'"},
        {sim + " -o out.csv --plot out.csv", "-o 'out.csv' and --plot 'out.csv'"},
        {sweep + " -o alias.txt --plot old.txt", "-o 'alias.txt' and --plot 'old.txt'"},
    };
    for (const auto& [args, message] : clashes) {
        CAPTURE(args);
        const Run run = yamsc(root, args);
        CHECK(run.status == 2);
        CHECK(run.err.find("usage error: " + message +
                           " are the same file (nothing was written)") != std::string::npos);
        for (const char* name : {"m.cpp", "m.hpp", "out.csv"})
            CHECK_FALSE(std::filesystem::exists(root + "/" + name));
        CHECK(read_file(root + "/old.txt") == "old\n");
        CHECK(temporaries(root).empty());
    }
}

TEST_CASE("a run that fails leaves the old outputs as they were") {
    const std::string root = scratch_dir("output_safety", "failed");
    write_inputs(root);
    write_file(root + "/in/bad_tower.dat", "not an ElastoDyn file\n");
    const std::vector<std::string> names{"m.cpp",   "m.hpp", "m.d",  "out.csv",
                                         "out.svg", "t.sid", "t.mbd"};
    for (const std::string& name : names) write_file(root + "/" + name, "old " + name + "\n");
    for (const std::string& args : {
             std::string("in/broken.mbd -o m.cpp --header m.hpp --depfile m.d"),
             std::string("in/broken.mbd --lang latex -o m.cpp --depfile m.d"),
             std::string("sim in/broken.mbd --tmax 1 --dt 0.1 -o out.csv --plot out.svg"),
             std::string("lin in/broken.mbd --sweep g=0:5:10 -o out.csv --plot out.svg"),
             std::string("sid --elastodyn-tower in/bad_tower.dat --length 87.6 -o t.sid"),
             std::string("from-openfast in/bad_tower.dat -o t.mbd"),
         }) {
        CAPTURE(args);
        CHECK(yamsc(root, args).status == 1);
        for (const std::string& name : names)
            CHECK(read_file(root + "/" + name) == "old " + name + "\n");
        CHECK(temporaries(root).empty());
    }
}

TEST_CASE("a socket, a folder or a loop of links as an output is refused; nothing is written") {
    const std::string root = scratch_dir("output_safety", "refused");
    write_inputs(root);
    // A listening Unix socket.
    const std::string socket_path = root + "/sock";
    const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
    REQUIRE(fd >= 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    REQUIRE(socket_path.size() < sizeof address.sun_path);
    std::strcpy(address.sun_path, socket_path.c_str());
    REQUIRE(::bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0);
    std::filesystem::create_directories(root + "/folder");
    REQUIRE(::symlink("loop_b", (root + "/loop_a").c_str()) == 0);
    REQUIRE(::symlink("loop_a", (root + "/loop_b").c_str()) == 0);
    const std::vector<std::pair<std::string, std::string>> refused{
        {"in/model.mbd -o sock --lang cpp", "cannot write 'sock': it is a socket, not a file"},
        {"in/model.mbd -o m.cpp --header sock", "cannot write 'sock': it is a socket"},
        {sim + " -o folder", "cannot write 'folder': it is a folder"},
        {sweep + " --plot loop_a", "cannot write 'loop_a': too many levels of symbolic links"},
        {"sid --elastodyn-tower " + tower + " --length 87.6 -o sock",
         "cannot write 'sock': it is a socket"},
    };
    for (const auto& [args, message] : refused) {
        CAPTURE(args);
        const Run run = yamsc(root, args);
        CHECK(run.status == 1);
        CHECK(run.err.find("error: " + message) != std::string::npos);
        CHECK(file_type(socket_path) == S_IFSOCK);
        CHECK_FALSE(std::filesystem::exists(root + "/m.cpp"));
        CHECK(temporaries(root).empty());
    }
    ::close(fd);
}

TEST_CASE("a replaced file keeps its permission bits") {
    const std::string root = scratch_dir("output_safety", "mode");
    write_inputs(root);
    const std::string out = root + "/private.sid";
    write_file(out, "old\n");
    REQUIRE(::chmod(out.c_str(), 0600) == 0);
    REQUIRE(
        yamsc(root, "sid --elastodyn-tower " + tower + " --length 87.6 -o private.sid").status ==
        0);
    struct stat st {};
    REQUIRE(::stat(out.c_str(), &st) == 0);
    CHECK((st.st_mode & 07777) == 0600);
    CHECK(read_file(out).size() > 100);
}
