#pragma once
// The commands of `yamsc` as library functions: each takes its options, writes
// its results to `out`, diagnostics and progress to `err`, and returns the exit
// status (0 success, 1 user error). Usage errors throw UsageError, internal
// errors diag::InternalError; the CLI turns them into exit statuses 2 and 70.
#include "driver/values.hpp"

#include <iosfwd>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace yamsc::driver {

struct CompileOptions {
    std::string model;
    std::string output;                     // -o
    std::string header;                     // --header
    std::string lang;                       // cpp | c | latex; empty: from the extension of -o
    std::string name_space;                 // --namespace
    std::string dump;                       // ast | model | equations | module: print and stop
    std::string depfile;                    // --depfile: make-style dependencies of the output
    std::string real;                       // --real float|double (C only); empty: double
    std::string jacobians;                  // --jacobians auto|unrolled|tangent; empty: auto
    std::vector<std::string> sensitivities; // --sensitivities p1,p2: d(M0,C0,K0)/dp routine
    bool verbose = false;                   // progress of each stage on stderr
};

struct CheckOptions {
    std::string model;
    bool json = false;
};

struct EvalOptions {
    std::string model;
    std::vector<double> q, qd;      // empty: zeros
    std::vector<Assignment> u, set; // --u, --set
    std::string sid;                // --sid body=file.sid,..
    double t = 0;
    bool json = true;
};

struct LinOptions {
    std::string model;
    std::vector<Assignment> at, set, u;
    std::string sid; // --sid body=file.sid,..
    bool json = false;
    std::string sweep;  // --sweep NAME=FROM:STEP:TO: a Campbell diagram
    std::string output; // -o: its CSV (default: stdout)
    std::string plot;   // --plot: its SVG
};

struct SimOptions {
    std::string model;
    double tmax = 0, dt = 0;
    std::vector<Assignment> ic, u, set;
    std::string sid;            // --sid body=file.sid,..
    std::string method = "rk4"; // rk4 | cvode
    std::string output;         // CSV path; empty: summary only
    double rtol = 1e-8, atol = 1e-10;
    bool verbose = false;
    std::string channels = "all";           // all | openfast (outputs named as OpenFAST channels)
    std::string compare;                    // reference table: print the error per channel
    std::string plot;                       // SVG of the channels (with the reference)
    std::vector<std::string> plot_channels; // --plot-channels; empty: compared or all
    bool linear = false;                    // integrate the linear model about --at / linearize
    std::vector<Assignment> at;             // --at: the operating point of --linear
};

struct FromOpenFastOptions {
    std::string deck;                               // ElastoDyn main file or .fst
    std::vector<std::pair<std::string, bool>> dofs; // --dofs NAME=on|off (ElastoDyn flag names)
    std::string output;                             // -o model.mbd
};

struct SidOptions {
    std::string tower, blade;       // --elastodyn-tower / --elastodyn-blade
    double length = 0;              // --length [m]
    std::vector<std::string> modes; // --modes fa1,ss1 (default: all first modes)
    int stations = 50;              // --stations: integration stations and SID nodes
    std::string output;             // -o; empty or "-": stdout
};

int compile(const CompileOptions& o, std::ostream& out, std::ostream& err);
int check(const CheckOptions& o, std::ostream& out, std::ostream& err);
int eval(const EvalOptions& o, std::ostream& out, std::ostream& err);
int lin(const LinOptions& o, std::ostream& out, std::ostream& err);
int sim(const SimOptions& o, std::ostream& out, std::ostream& err);
int sid(const SidOptions& o, std::ostream& out, std::ostream& err);
int from_openfast(const FromOpenFastOptions& o, std::ostream& out, std::ostream& err);

} // namespace yamsc::driver
