#include <yamsc/hydro/wave_elevation.hpp>

#include <stdexcept>

namespace yamsc::runtime::hydro {
namespace {

class WaveElevation final : public LoadBlock {
public:
    WaveElevation(std::shared_ptr<const WaveField> field, std::vector<ElevationPoint> points,
                  std::string prefix)
        : field_(std::move(field)), points_(std::move(points)), prefix_(std::move(prefix)) {
        if (points_.empty()) throw std::invalid_argument("wave elevation: no points");
    }

    const BlockPorts& ports() const override { return ports_; }

    std::vector<std::string> output_names() const override {
        std::vector<std::string> names;
        for (std::size_t k = 1; k <= points_.size(); ++k)
            names.push_back(prefix_ + "Wave" + std::to_string(k) + "Elev");
        return names;
    }

    void evaluate(double t, const double*, const double*, double*, double*,
                  double* out) const override {
        for (std::size_t k = 0; k < points_.size(); ++k)
            out[k] = field_ ? field_->elevation(t, points_[k].x, points_[k].y) : 0.0;
    }

    // Nothing read, nothing loaded: no derivatives.
    void derivatives(double, const double*, const double*, BlockJacobian& j) const override {
        j = {};
    }

private:
    std::shared_ptr<const WaveField> field_;
    std::vector<ElevationPoint> points_;
    std::string prefix_;
    BlockPorts ports_;
};

} // namespace

std::shared_ptr<const LoadBlock> wave_elevation_block(std::shared_ptr<const WaveField> field,
                                                      std::vector<ElevationPoint> points,
                                                      std::string output_prefix) {
    return std::make_shared<WaveElevation>(std::move(field), std::move(points),
                                           std::move(output_prefix));
}

} // namespace yamsc::runtime::hydro
