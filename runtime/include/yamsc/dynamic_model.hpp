#pragma once
// A generated model compiled into a shared library (with abi_export.hpp's
// YAMSC_EXPORT_MODEL) and loaded at run time, as `yamsc sim` does.
#include "yamsc/model_view.hpp"

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace yamsc::runtime {

/// Loading failed: the file is missing or not a library, the ABI version
/// differs, or a symbol is missing. The message says which.
class SharedModelError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class SharedModel {
public:
    /// dlopens `path` and checks the ABI version, the model's information
    /// symbols, rhs and the sizes. The other routines may be absent.
    explicit SharedModel(const std::string& path);

    const std::string& path() const { return path_; }
    int nq() const { return nq_; }
    int nu() const { return nu_; }
    int np() const { return np_; }
    int ny() const { return ny_; }
    const std::vector<std::string>& dof_names() const { return dof_names_; }
    const std::vector<std::string>& input_names() const { return input_names_; }
    const std::vector<std::string>& param_names() const { return param_names_; }
    const std::vector<std::string>& output_names() const { return output_names_; }

    /// The model's defaults in declaration order; NaN where a parameter has no default.
    std::vector<double> default_params() const;
    /// The routines the library holds (rhs always), in the ABI's order.
    std::vector<std::string> routines() const;
    /// The index of a parameter, or -1.
    int param_index(const std::string& name) const;

    /// A view with the parameters bound (np values). Throws std::invalid_argument
    /// on a wrong count or a NaN value (a parameter without default left unset),
    /// naming the parameter. Routines the library lacks are empty functions in
    /// the view. The view keeps the library loaded: it stays valid
    /// after this SharedModel is destroyed.
    ModelView view(std::vector<double> params) const;

private:
    struct Library;
    void read_constraints(Library& library, void* handle);
    std::shared_ptr<const Library> library_;
    std::string path_;
    int nq_ = 0, nu_ = 0, np_ = 0, ny_ = 0;
    std::vector<std::string> dof_names_, input_names_, param_names_, output_names_;
    int nh_ = 0, nc_ = 0; // constraint rows (yamsc_constraint_sizes; 0 without)
    std::vector<std::string> constraint_names_, constraint_sources_;
    std::vector<int> constraint_dependent_;
};

} // namespace yamsc::runtime
