// `yamsc batch` through the yamsc binary: a case gives `yamsc sim`'s file byte
// for byte; threads, shards and a run killed and resumed all give the same
// files as one uninterrupted run (1000 cases, killed by SIGKILL or SIGINT); bad rows are reported
// at their place in the manifest while the other cases run; an edited row is run again.
#include "test_files.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <dirent.h>
#include <random>
#include <string>
#include <vector>

using namespace test_support;

namespace {

struct Run {
    int status;
    std::string out, err;
};

const std::string source_dir = YAMSC_SOURCE_DIR;
const std::string floating = source_dir + "/models/nrel5mw_floating_3dof.mbd";

/// Runs `command` in `dir` (yamsc is $Y) with the tests' model cache, kept
/// across tests so that the model is compiled once.
Run run_in(const std::string& dir, const std::string& command) {
    const std::string cache = std::string(YAMSC_TEST_BINARY_DIR) + "/batch-cache";
    const std::string log = dir + "/.log";
    write_file(log + ".sh", command + "\n");
    const int status =
        exit_status("cd '" + dir + "' && Y='" + YAMSC_EXE + "' YAMSC_CACHE_DIR='" + cache +
                    "' sh '" + log + ".sh' >'" + log + ".out' 2>'" + log + ".err'");
    return {status, read_file(log + ".out"), read_file(log + ".err")};
}

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

/// The names in `dir` ending in `ext`, sorted; not the summaries.
std::vector<std::string> files_of(const std::string& dir, const std::string& ext) {
    std::vector<std::string> out;
    if (DIR* d = ::opendir(dir.c_str())) {
        while (const dirent* e = ::readdir(d)) {
            const std::string n = e->d_name;
            if (n.size() > ext.size() && n.compare(n.size() - ext.size(), ext.size(), ext) == 0 &&
                n.rfind("summary", 0) != 0)
                out.push_back(n);
        }
        ::closedir(d);
    }
    std::sort(out.begin(), out.end());
    return out;
}

/// A summary without its last column (the wall time of each case).
std::string without_wall_times(const std::string& summary) {
    std::string out;
    std::size_t start = 0;
    while (start < summary.size()) {
        const std::size_t end = summary.find('\n', start);
        const std::string line = summary.substr(start, end - start);
        out += line.substr(0, line.rfind(',')) + "\n";
        start = end == std::string::npos ? summary.size() : end + 1;
    }
    return out;
}

/// Every case's result and the summary of `a` and `b` are the same (but the wall times).
void check_same_results(const std::string& a, const std::string& b, const std::string& summary_a,
                        const std::string& summary_b) {
    const std::vector<std::string> results = files_of(a, ".csv");
    REQUIRE(results == files_of(b, ".csv"));
    for (const std::string& f : results) {
        INFO(f);
        CHECK(read_file(a + "/" + f) == read_file(b + "/" + f));
    }
    CHECK(without_wall_times(read_file(a + "/" + summary_a)) ==
          without_wall_times(read_file(b + "/" + summary_b)));
}

/// A parameter sweep of the floating 3-DOF model: floater mass, shaft tilt
/// and the initial pitch; `n` cases of 2 s.
std::string sweep_manifest(int n) {
    std::string m = "id,model,tmax,dt,set:M_F,set:theta_t,ic:phi_y\n";
    for (int i = 0; i < n; ++i)
        m += "case" + std::to_string(i) + "," + floating + ",2,0.05," +
             std::to_string(6.5e6 + 1e4 * (i % 17)) + "," + std::to_string(i % 7) + "deg," +
             std::to_string(0.01 + 0.001 * i) + "\n";
    return m;
}

} // namespace

TEST_CASE("a batch case writes the file `yamsc sim` writes with the same options") {
    const std::string dir = scratch_dir("batch", "same_as_sim");
    write_file(dir + "/wind.csv", "time,V_wind\n0,8\n1,12\n");
    write_file(dir + "/cases.csv", "id,model,tmax,dt,set,ic,u,method\n"
                                   "plain," +
                                       floating +
                                       ",3,0.02,,,,\n"
                                       "swept," +
                                       floating +
                                       ",3,0.02,\"M_F=7e6,theta_t=4deg\",\"phi_y=0.02,x'=0.1\","
                                       "\"f_a=8e5,f_H=1e5\",\n"
                                       "stiff," +
                                       floating + ",3,0.1,M_F=8e6,phi_y=-0.01,,cvode\n");
    const Run b = run_in(dir, "$Y batch cases.csv -o out --threads 2");
    INFO(b.err);
    REQUIRE(b.status == 0);
    CHECK(has(b.out, "3 cases, 3 ok, 0 failed"));
    const Run s = run_in(
        dir, "$Y sim " + floating + " --tmax 3 --dt 0.02 -o plain.csv && $Y sim " + floating +
                 " --tmax 3 --dt 0.02 --set M_F=7e6,theta_t=4deg --ic phi_y=0.02,x\\'=0.1 "
                 "--u f_a=8e5,f_H=1e5 -o swept.csv && $Y sim " +
                 floating +
                 " --tmax 3 --dt 0.1 --set M_F=8e6 --ic phi_y=-0.01 --method cvode -o stiff.csv");
    INFO(s.err);
    REQUIRE(s.status == 0);
    for (const char* id : {"plain", "swept", "stiff"}) {
        INFO(id);
        const std::string from_sim = read_file(dir + "/" + id + ".csv");
        CHECK(from_sim.size() > 1000);
        CHECK(read_file(dir + "/out/" + id + ".csv") == from_sim);
    }
    // The summary: one line per case with the final values of the run.
    const std::string summary = read_file(dir + "/out/summary.csv");
    CHECK(summary.rfind("row,id,status,final,message,wall_s\n1,plain,ok,\"time=3,x=", 0) == 0);
}

TEST_CASE("a turbine case with a controller, loose coupling, OpenFAST's channels and dt_out is "
          "the `yamsc sim` run") {
    const std::string dir = scratch_dir("batch", "turbine_options");
    const std::string operating = source_dir + "/models/nrel5mw_land_operating.mbd";
    const std::string table = source_dir + "/models/data/Cp_Ct_Cq.NREL5MW.txt";
    run_in(dir, "mkdir -p in && cp '" + table + "' in/table.txt && cp '" +
                    YAMSC_MISBEHAVING_DISCON + "' in/discon.so");
    write_file(dir + "/in/hold.in", "hold 20000\n");
    write_file(dir + "/in/cases.csv",
               "id,model,tmax,dt,method,aero,wind,controller,controller_input,coupling,"
               "interp_order,channels,dt_out\n"
               "loose," +
                   operating +
                   ",2,0.01,abm4,table.txt,9,discon.so,hold.in,loose,1,openfast,0.05\n"
                   "tight," +
                   operating + ",2,0.01,,table.txt,9,discon.so,hold.in,,,,\n");
    const Run b = run_in(dir, "$Y batch in/cases.csv -o out --threads 2");
    INFO(b.err);
    REQUIRE(b.status == 0);
    const Run s = run_in(dir, "cd in && $Y sim " + operating +
                                  " --tmax 2 --dt 0.01 --method abm4 --aero table.txt --wind 9 "
                                  "--controller ./discon.so --controller-input hold.in --coupling "
                                  "loose --interp-order 1 --channels openfast --dt-out 0.05 -o "
                                  "../loose.csv && $Y sim " +
                                  operating +
                                  " --tmax 2 --dt 0.01 --aero table.txt --wind 9 --controller "
                                  "./discon.so --controller-input hold.in -o ../tight.csv");
    INFO(s.err);
    REQUIRE(s.status == 0);
    for (const char* id : {"loose", "tight"}) {
        INFO(id);
        CHECK(read_file(dir + "/" + id + ".csv").size() > 1000);
        CHECK(read_file(dir + "/out/" + id + ".csv") == read_file(dir + "/" + id + ".csv"));
    }
    CHECK(read_file(dir + "/out/loose.csv").rfind("Time_[s],", 0) == 0); // OpenFAST's names
    // The controller and its input are inputs of the case: a changed input runs it again.
    write_file(dir + "/in/hold.in", "hold 21000\n");
    const Run again = run_in(dir, "$Y batch in/cases.csv -o out");
    CHECK(has(again.err, "2 cases, 0 done before, 2 to run"));
    // A result may not replace the controller.
    write_file(dir + "/in/own.csv",
               "id,model,tmax,dt,controller\ndiscon.so," + operating + ",1,0.01,discon.so.csv\n");
    run_in(dir, "cp in/discon.so in/discon.so.csv");
    const Run own = run_in(dir, "$Y batch in/own.csv -o in");
    CHECK(own.status == 1);
    CHECK(has(own.err, "would replace"));
    // Combinations sim refuses are refused at their place.
    write_file(dir + "/in/bad.csv", "id,model,tmax,dt,method,coupling,interp_order,dt_out\n"
                                    "a," +
                                        operating +
                                        ",1,0.01,cvode,loose,,\n"
                                        "b," +
                                        operating +
                                        ",1,0.01,,,1,\n"
                                        "c," +
                                        operating + ",1,0.01,,,,0.015\n");
    const Run bad = run_in(dir, "$Y batch in/bad.csv -o bad");
    CHECK(bad.status == 1);
    const std::size_t coupling_col = 3 + operating.size() + std::string(",1,0.01,cvode,").size();
    CHECK(has(bad.err, "in/bad.csv:2:" + std::to_string(coupling_col) +
                           ": error: coupling loose steps with rk4 or abm4"));
    CHECK(has(bad.err, ": error: interp_order needs coupling loose"));
    CHECK(has(bad.err, ": error: dt_out must be a positive multiple of dt"));
}

TEST_CASE("a case that crashes, hangs, exits or diverges fails alone, with its reason") {
    const std::string dir = scratch_dir("batch", "isolation");
    const std::string operating = source_dir + "/models/nrel5mw_land_operating.mbd";
    const std::string table = source_dir + "/models/data/Cp_Ct_Cq.NREL5MW.txt";
    run_in(dir, "cp '" + table + "' table.txt && cp '" + YAMSC_MISBEHAVING_DISCON + "' discon.so");
    std::string manifest = "id,model,tmax,dt,aero,wind,controller,controller_input\n";
    for (const char* mode : {"hold 20000", "segv", "loop", "nan", "exit", "hold 30000"}) {
        std::string id = mode;
        id = id.substr(0, id.find(' ')) + (id.size() > 5 ? id.substr(5, 2) : "");
        write_file(dir + "/" + id + ".in", std::string(mode) + "\n");
        manifest += id + "," + operating + ",2,0.01,table.txt,9,discon.so," + id + ".in\n";
    }
    write_file(dir + "/cases.csv", manifest);
    const auto start = std::chrono::steady_clock::now();
    const Run b = run_in(dir, "$Y batch cases.csv -o out --threads 2 --case-time-limit 2");
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    INFO(b.err);
    CHECK(b.status == 1);
    CHECK(has(b.out, "6 cases, 2 ok, 4 failed"));
    // The hanging case is stopped at its limit; the others take milliseconds.
    MESSAGE("wall time " << wall << " s");
    CHECK(wall < 8);
    const std::string summary = read_file(dir + "/out/summary.csv");
    INFO(summary);
    CHECK(has(summary, "2,segv,error,,\"cases.csv:3:1: error: killed by SIGSEGV"));
    CHECK(has(summary, "3,loop,error,,cases.csv:4:1: error: time limit of 2 s exceeded"));
    CHECK(has(summary, "4,nan,error,,cases.csv:5:1: error: the controller demanded a pitch of "
                       "nan rad"));
    CHECK(has(summary, "5,exit,error,,cases.csv:6:1: error: the case's process exited with "
                       "status 3"));
    CHECK(has(b.err, "cases.csv:3:1: error: killed by SIGSEGV"));
    // The diverged case says when.
    const std::size_t nan_at = summary.find("4,nan,error");
    CHECK(has(summary.substr(nan_at, summary.find('\n', nan_at) - nan_at), "at t = 0.5"));
    // No result of a failed case, nothing half-written.
    CHECK(files_of(dir + "/out", ".csv") == std::vector<std::string>{"hold20.csv", "hold30.csv"});
    CHECK(temporaries(dir + "/out").empty());
    const Run s = run_in(dir, "$Y sim " + operating +
                                  " --tmax 2 --dt 0.01 --aero table.txt --wind 9 --controller "
                                  "./discon.so --controller-input hold20.in -o hold20.csv && $Y "
                                  "sim " +
                                  operating +
                                  " --tmax 2 --dt 0.01 --aero table.txt --wind 9 --controller "
                                  "./discon.so --controller-input hold30.in -o hold30.csv");
    REQUIRE(s.status == 0);
    for (const char* id : {"hold20", "hold30"}) {
        INFO(id);
        CHECK(read_file(dir + "/out/" + id + ".csv") == read_file(dir + "/" + id + ".csv"));
    }
    // A time_limit column wins over --case-time-limit, row by row.
    write_file(dir + "/limit.csv", "id,model,tmax,dt,aero,wind,controller,controller_input,"
                                   "time_limit\nloop," +
                                       operating + ",2,0.01,table.txt,9,discon.so,loop.in,1\n");
    const Run limited = run_in(dir, "$Y batch limit.csv -o limited --case-time-limit 100");
    CHECK(has(limited.err, "limit.csv:2:1: error: time limit of 1 s exceeded"));
}

TEST_CASE("wind and rotor table files are relative to the manifest; a missing one is located") {
    const std::string dir = scratch_dir("batch", "wind");
    const std::string operating = source_dir + "/models/nrel5mw_land_operating.mbd";
    const std::string table = source_dir + "/models/data/Cp_Ct_Cq.NREL5MW.txt";
    run_in(dir, "mkdir -p dlc && cp '" + table + "' dlc/table.txt");
    write_file(dir + "/dlc/gust.csv", "time,V_wind\n0,8\n0.5,8\n1,12\n2,10\n");
    write_file(dir + "/dlc/cases.csv", "id,model,tmax,dt,aero,wind,set:air_density\n"
                                       "steady," +
                                           operating +
                                           ",2,0.01,table.txt,9,\n"
                                           "gust," +
                                           operating +
                                           ",2,0.01,table.txt,gust.csv,1.1\n"
                                           "lost," +
                                           operating + ",2,0.01,table.txt,lost.csv,\n");
    const Run b = run_in(dir, "$Y batch dlc/cases.csv -o out");
    INFO(b.err);
    CHECK(b.status == 1);
    CHECK(has(b.out, "3 cases, 2 ok, 1 failed"));
    const std::size_t wind_col = std::string("lost,").size() + operating.size() +
                                 std::string(",2,0.01,table.txt,").size() + 1;
    CHECK(has(b.err, "dlc/cases.csv:4:" + std::to_string(wind_col) +
                         ": error: cannot read the wind file 'dlc/lost.csv'"));
    const Run s = run_in(dir, "cd dlc && $Y sim " + operating +
                                  " --tmax 2 --dt 0.01 --aero table.txt --wind 9 -o ../steady.csv "
                                  "&& $Y sim " +
                                  operating +
                                  " --tmax 2 --dt 0.01 --aero table.txt --wind gust.csv "
                                  "--set air_density=1.1 -o ../gust.csv");
    INFO(s.err);
    REQUIRE(s.status == 0);
    for (const char* id : {"steady", "gust"}) {
        INFO(id);
        CHECK(read_file(dir + "/out/" + id + ".csv") == read_file(dir + "/" + id + ".csv"));
    }
    CHECK(read_file(dir + "/out/gust.csv") != read_file(dir + "/out/steady.csv"));
    // A wind file that changed reruns the cases that read it.
    write_file(dir + "/dlc/gust.csv", "time,V_wind\n0,8\n0.5,8\n1,13\n2,10\n");
    const Run again = run_in(dir, "$Y batch dlc/cases.csv -o out");
    CHECK(has(again.err, "3 cases, 1 done before, 1 to run"));
    CHECK(read_file(dir + "/out/gust.csv") != read_file(dir + "/gust.csv"));
}

TEST_CASE("threads, shards and a run killed with SIGKILL or SIGINT and resumed give one run's "
          "files") {
    const int n = 1000;
    const std::string dir = scratch_dir("batch", "sweep");
    write_file(dir + "/cases.csv", sweep_manifest(n));

    const Run one = run_in(dir, "$Y batch cases.csv -o one --threads 1");
    INFO(one.err);
    REQUIRE(one.status == 0);
    CHECK(has(one.out, "1000 cases, 1000 ok, 0 failed"));
    CHECK(files_of(dir + "/one", ".csv").size() == n);

    SUBCASE("two threads") {
        const Run two = run_in(dir, "$Y batch cases.csv -o two --threads 2");
        REQUIRE(two.status == 0);
        check_same_results(dir + "/one", dir + "/two", "summary.csv", "summary.csv");
    }
    SUBCASE("four shards and merge") {
        const Run shards = run_in(dir, "for k in 1 2 3 4; do $Y batch cases.csv -o shards "
                                       "--shard $k/4 --threads 1 || exit 1; done && "
                                       "$Y batch merge shards");
        INFO(shards.err);
        REQUIRE(shards.status == 0);
        CHECK(has(shards.out, "batch merge: 4 shards, 1000 cases, 1000 ok, 0 failed"));
        check_same_results(dir + "/one", dir + "/shards", "summary.csv", "summary.csv");
        // Shard 2 of 4 holds rows 2, 6, 10, ...
        const std::string s2 = read_file(dir + "/shards/summary-2-of-4.csv");
        CHECK(s2.find("\n2,case1,ok,") != std::string::npos);
        CHECK(s2.find("\n6,case5,ok,") != std::string::npos);
        CHECK(s2.find(",case0,") == std::string::npos);
        // A missing shard is an error.
        const Run missing = run_in(dir, "mkdir -p partial && cp shards/summary-1-of-4.csv "
                                        "partial/ && $Y batch merge partial");
        CHECK(missing.status == 1);
        CHECK(has(missing.err, "missing shards: 2/4, 3/4, 4/4"));
    }
    // Killed once a random number of results is written (polled every 5 ms):
    // a point inside the run whatever the machine's speed. SIGKILL leaves what
    // a crash leaves; SIGINT (Ctrl-C) lets the cases in progress finish.
    for (const char* signal : {"KILL", "INT"}) {
        SUBCASE(
            (std::string("killed by SIG") + signal + " at a random point, then resumed").c_str()) {
            std::random_device seed;
            std::mt19937 random(seed());
            const int at = std::uniform_int_distribution<int>(n / 10, n * 8 / 10)(random);
            MESSAGE("SIG" << std::string(signal) << " after " << at << " of " << n << " results");
            // yamsc in the foreground (a background job of sh ignores SIGINT),
            // the signal from a watcher in the background.
            const Run killed = run_in(
                dir, "rm -f pid\n(while [ ! -s pid ] || [ $(ls resumed 2>/dev/null | grep -c "
                     "'csv$') -lt " +
                         std::to_string(at) + " ]; do sleep 0.005; done; kill -" + signal +
                         " $(cat pid)) &\nsh -c 'echo $$ > pid; exec \"$Y\" batch cases.csv -o "
                         "resumed --threads 2 -q'\necho killed $?\nwait");
            CHECK(has(killed.out, std::string("killed ") + (signal[0] == 'K' ? "137" : "130")));
            if (signal[0] == 'I') CHECK(has(killed.err, "batch interrupted after"));
            const Run resumed = run_in(dir, "$Y batch cases.csv -o resumed --threads 2");
            INFO(resumed.err);
            REQUIRE(resumed.status == 0);
            const std::size_t done_before =
                std::stoul(resumed.err.substr(resumed.err.find(", ") + 2));
            MESSAGE(done_before << " cases done before resuming");
            CHECK(done_before >= static_cast<std::size_t>(at) - 2); // records lag the results
            CHECK(done_before < static_cast<std::size_t>(n));
            check_same_results(dir + "/one", dir + "/resumed", "summary.csv", "summary.csv");
            CHECK(temporaries(dir + "/resumed").empty());
            // A third run has nothing left to do.
            const Run again = run_in(dir, "$Y batch cases.csv -o resumed");
            CHECK(again.status == 0);
            CHECK(has(again.err, "1000 done before, 0 to run"));
        }
    }
}

TEST_CASE("bad rows are reported at their place; the other cases run; exit status 1") {
    const std::string dir = scratch_dir("batch", "bad_rows");
    // MODEL stands for the floating model's path.
    const std::string manifest = "# a comment line, then the header\n"
                                 "id,model,tmax,dt,set,ic:phi_y\n"
                                 "good1,MODEL,1,0.1,,0.01\n"
                                 "unknown,MODEL,1,0.1,\"M_F=7e6,M_Q=3\",0\n"
                                 "missing,no/such.mbd,1,0.1,,0\n"
                                 "nan,MODEL,1,0.1,,nan\n"
                                 "good1,MODEL,1,0.1,,0.02\n"
                                 "short,MODEL,1\n"
                                 "bad/id,MODEL,1,0.1,,0\n"
                                 "summary,MODEL,1,0.1,,0\n"
                                 "good2,MODEL,1,0.1,M_F=7e6,0.03\n"
                                 "broken,broken.mbd,1,0.1,,0\n"
                                 "open,MODEL,1,0.1,\"M_F=7e6,0\n";
    write_file(dir + "/broken.mbd", "model broken\ndof phi_y\nparam k = q\n");
    write_file(dir + "/cases.csv", replace_all(manifest, "MODEL", floating));
    const Run r = run_in(dir, "$Y batch cases.csv --threads 2");
    INFO(r.err);
    CHECK(r.status == 1);
    CHECK(has(r.out, "11 cases, 2 ok, 9 failed"));
    const std::string m = "cases.csv:";
    // M_Q's column: after the id, the model, the times, the quote and M_F=7e6,.
    const std::size_t q_col = std::string("unknown,").size() + floating.size() +
                              std::string(",1,0.1,\"M_F=7e6,").size() + 1;
    CHECK(has(r.err, m + "4:" + std::to_string(q_col) +
                         ": error: unknown parameter 'M_Q' (did you mean 'M_F'?)"));
    CHECK(has(r.err, m + "5:9: error: cannot read the model 'no/such.mbd'"));
    CHECK(has(r.err, ": error: ic:phi_y: 'nan' is not a number"));
    CHECK(has(r.err, m + "7:1: error: the id 'good1' is already used at cases.csv:3:1"));
    CHECK(has(r.err, m + "8:1: error: 3 fields, the header has 6"));
    CHECK(has(r.err, m + "9:1: error: the id 'bad/id' is not a file name"));
    const std::size_t quote_col =
        std::string("open,").size() + floating.size() + std::string(",1,0.1,").size() + 1;
    CHECK(has(r.err,
              m + "13:" + std::to_string(quote_col) + ": error: the quoted field is not closed"));
    const std::string summary = read_file(dir + "/cases.out/summary.csv");
    CHECK(has(summary, "\n1,good1,ok,"));
    CHECK(has(r.err, m + "10:1: error: the id 'summary' would name the summary's file"));
    CHECK(has(summary, "\n9,good2,ok,"));
    // A model with errors: its diagnostics once on stderr, in the summary for its rows.
    CHECK(has(summary, "\n10,broken,error,,cases.csv:12:8: error: the model 'broken.mbd' has "
                       "errors: broken.mbd:3:11: error: unknown name 'q'"));
    CHECK(has(summary, "\n3,missing,error,,cases.csv:5:9: error: cannot read the model"));
    CHECK(files_of(dir + "/cases.out", ".csv") ==
          std::vector<std::string>{"good1.csv", "good2.csv"});
}

TEST_CASE("an edited row runs again; the others are kept") {
    const std::string dir = scratch_dir("batch", "edited");
    write_file(dir + "/cases.csv", sweep_manifest(5));
    REQUIRE(run_in(dir, "$Y batch cases.csv -o out").status == 0);
    const std::string case3 = read_file(dir + "/out/case3.csv");
    std::string edited = sweep_manifest(5);
    edited = replace_all(edited, "case3," + floating + ",2,", "case3," + floating + ",1,");
    write_file(dir + "/cases.csv", edited);
    const Run r = run_in(dir, "$Y batch cases.csv -o out");
    INFO(r.err);
    CHECK(r.status == 0);
    CHECK(has(r.err, "5 cases, 4 done before, 1 to run"));
    CHECK(read_file(dir + "/out/case3.csv") != case3);
    CHECK(read_file(dir + "/out/case3.csv").size() < case3.size());

    // A row that fails now leaves no result from before; one whose result
    // would replace the manifest is refused.
    edited = replace_all(edited, "set:M_F,", "set:M_Q,");
    write_file(dir + "/cases.csv", edited);
    const Run failing = run_in(dir, "$Y batch cases.csv -o out");
    CHECK(failing.status == 1);
    CHECK(has(failing.err, "cases.csv:2:"));
    CHECK(has(failing.err, ": error: unknown parameter 'M_Q'"));
    CHECK(files_of(dir + "/out", ".csv").empty());
    write_file(dir + "/cases.csv", "id,model,tmax,dt\ncases," + floating + ",1,0.1\n");
    const Run itself = run_in(dir, "$Y batch cases.csv -o .");
    CHECK(itself.status == 1);
    CHECK(has(itself.err, "/cases.csv would replace "));
    CHECK(read_file(dir + "/cases.csv").rfind("id,model", 0) == 0);
}

TEST_CASE("constrained models run as `yamsc sim` runs them; a bad start fails its case alone") {
    const std::string dir = scratch_dir("batch", "constrained");
    const std::string slider = source_dir + "/models/slider_crank.mbd";
    const std::string four_bar = source_dir + "/models/four_bar.mbd";
    write_file(dir + "/cases.csv", "id,model,tmax,dt,ic\n"
                                   "plain," +
                                       slider +
                                       ",1,0.01,\n"
                                       "turned," +
                                       slider +
                                       ",1,0.01,th=1\n"
                                       "singular," +
                                       four_bar + ",1,0.01,\"th2=0,phi3=0,th4=0\"\n");
    const Run b = run_in(dir, "$Y batch cases.csv -o out --threads 2");
    INFO(b.err);
    CHECK(b.status == 1);
    CHECK(has(b.out, "3 cases, 2 ok, 1 failed"));
    const Run s = run_in(dir, "$Y sim " + slider + " --tmax 1 --dt 0.01 -o plain.csv && $Y sim " +
                                  slider + " --tmax 1 --dt 0.01 --ic th=1 -o turned.csv");
    INFO(s.err);
    REQUIRE(s.status == 0);
    for (const char* id : {"plain", "turned"}) {
        INFO(id);
        const std::string from_sim = read_file(dir + "/" + id + ".csv");
        CHECK(has(from_sim, "constraint_position_error"));
        CHECK(read_file(dir + "/out/" + id + ".csv") == from_sim);
    }
    // The failed case names the row and where the model declares it.
    const std::string summary = read_file(dir + "/out/summary.csv");
    CHECK(has(summary, "3,singular,error,,cases.csv:4:1: error: "));
    CHECK(has(summary, "four_bar.mbd:40:1"));
    CHECK(has(summary, "redundant"));
}
