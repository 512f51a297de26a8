#pragma once
// The three kinds of failure a command can end with, defined once. The CLI
// (compiler/cli/main.cpp) maps each to its exit status; every stage throws one
// of these or reports located diagnostics (diagnostics.hpp), never anything else
// on purpose (any other std::exception reaching the CLI is reported as exit 1).
#include <stdexcept>
#include <string>

namespace yamsc::diag {

/// The command line is wrong: an unknown option, a malformed value, an output
/// that would replace an input. Exit 2, with the usage text.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// A user error found outside the model file (a parameter without a value, an
/// unknown name in --set, a controller that failed). Exit 1. Errors inside the
/// model file are diagnostics with file:line:col instead.
struct UserError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// An internal error: a bug in yamsc, not in the model. Exit 70.
struct InternalError : std::exception {
    explicit InternalError(std::string what) : what_(std::move(what)) {}
    const char* what() const noexcept override { return what_.c_str(); }

private:
    std::string what_;
};

} // namespace yamsc::diag
