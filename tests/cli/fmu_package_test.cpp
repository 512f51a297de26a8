// The pieces of `yamsc fmu` that need no compiler: the stored ZIP writer and
// the model description from a value-reference table (tests/fmi_e2e drives
// whole units).
#include "analysis/fmu_description.hpp"
#include "analysis/zip_store.hpp"

#include <doctest/doctest.h>

#include <cstdint>
#include <stdexcept>

using namespace yamsc;

namespace {

std::uint32_t u32(const std::string& s, std::size_t at) {
    std::uint32_t v = 0;
    for (int k = 3; k >= 0; --k)
        v = (v << 8) | static_cast<unsigned char>(s[at + static_cast<std::size_t>(k)]);
    return v;
}

std::uint32_t u16(const std::string& s, std::size_t at) {
    return static_cast<unsigned char>(s[at]) | (static_cast<unsigned char>(s[at + 1]) << 8U);
}

} // namespace

TEST_CASE("CRC-32 and the stored ZIP archive") {
    // The check value of the CRC-32 ZIP uses (ISO 3309).
    CHECK(analysis::crc32("123456789") == 0xCBF43926U);
    CHECK(analysis::crc32("") == 0U);
    const std::string zip = analysis::zip_stored(
        {{"modelDescription.xml", "<x/>"}, {"binaries/", ""}, {"binaries/a.so", "ELF", true}});
    // Local header of the first entry: signature, stored, CRC and sizes, the name, the data.
    CHECK(u32(zip, 0) == 0x04034B50U);
    CHECK(u16(zip, 8) == 0U);
    CHECK(u32(zip, 14) == analysis::crc32("<x/>"));
    CHECK(u32(zip, 18) == 4U);
    CHECK(zip.substr(30, 20) == "modelDescription.xml");
    CHECK(zip.substr(50, 4) == "<x/>");
    // The end record: three entries, the directory right before it.
    const std::size_t end = zip.size() - 22;
    CHECK(u32(zip, end) == 0x06054B50U);
    CHECK(u16(zip, end + 10) == 3U);
    CHECK(u32(zip, end + 16) + u32(zip, end + 12) == end);
    CHECK(u32(zip, u32(zip, end + 16)) == 0x02014B50U);
    // The same entries give the same bytes (a fixed date).
    CHECK(zip == analysis::zip_stored({{"modelDescription.xml", "<x/>"},
                                       {"binaries/", ""},
                                       {"binaries/a.so", "ELF", true}}));
    CHECK_THROWS_AS(analysis::zip_stored({{"../x", "a"}}), std::invalid_argument);
    CHECK_THROWS_AS(analysis::zip_stored({{"/x", "a"}}), std::invalid_argument);
    CHECK_THROWS_AS(analysis::zip_stored({{"a\\b", "a"}}), std::invalid_argument);
    CHECK_THROWS_AS(analysis::zip_stored({{"x", "a"}, {"x", "b"}}), std::invalid_argument);
    CHECK_THROWS_AS(analysis::zip_stored({{"d/", "data"}}), std::invalid_argument);
}

TEST_CASE("units and descriptions from the model's comments") {
    CHECK(analysis::unit_in("tip height [m]") == "m");
    CHECK(analysis::unit_in("elbow damping [N m s/rad] ") == "N m s/rad");
    CHECK(analysis::unit_in("no unit") == "");
    CHECK(analysis::unit_in("[rad]") == "rad");
    CHECK(analysis::without_unit("tip height [m]") == "tip height");
    CHECK(analysis::without_unit("no unit") == "no unit");
}

TEST_CASE("the model description follows the value-reference table") {
    fmi::UnitLayout l;
    l.dof_names = {"th"};
    l.input_names = {"tau"};
    l.param_names = {"m"};
    l.param_values = {2.0};
    l.output_names = {"x_tip"};
    l.initial_state = {0.5, 0.0};
    l.dof_docs = {"angle [rad]"};
    l.input_docs = {"torque [N m]"};
    l.param_docs = {"mass [kg]"};
    l.output_docs = {"tip position [m]"};
    analysis::DescriptionFacts f;
    f.model_name = "p";
    f.token = "{t}";
    f.step = 0.01;
    f.variables = fmi::variables(l);
    const std::string v3 = analysis::model_description(f);
    CHECK(v3.find("fmiVersion=\"3.0\"") != std::string::npos);
    CHECK(v3.find("<Float64 name=\"th\" valueReference=\"1\" description=\"angle\" "
                  "causality=\"local\" variability=\"continuous\" initial=\"exact\" "
                  "unit=\"rad\" start=\"0.5\"/>") != std::string::npos);
    // The rate is the derivative of q and a state; q'' the derivative of the rate.
    CHECK(v3.find("name=\"th&apos;\" valueReference=\"2\"") != std::string::npos);
    CHECK(v3.find("unit=\"rad/s\" derivative=\"1\"") != std::string::npos);
    CHECK(v3.find("unit=\"rad/s2\" derivative=\"2\"") != std::string::npos);
    CHECK(v3.find("<Unit name=\"N m\"/>") != std::string::npos);
    CHECK(v3.find("<ContinuousStateDerivative valueReference=\"2\" dependencies=\"2\"/>") !=
          std::string::npos);
    CHECK(v3.find("fixedInternalStepSize=\"0.01\"") != std::string::npos);
    f.version = driver::FmiVersion::fmi2;
    const std::string v2 = analysis::model_description(f);
    CHECK(v2.find("fmiVersion=\"2.0\"") != std::string::npos);
    CHECK(v2.find("guid=\"{t}\"") != std::string::npos);
    // FMI 2.0 names variables by index (value reference + 1).
    CHECK(v2.find("<Real unit=\"rad/s\" derivative=\"2\" start=\"0\"/>") != std::string::npos);
    CHECK(v2.find("<Unknown index=\"3\" dependencies=\"3\"/>") != std::string::npos);
}
