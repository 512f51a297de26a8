#pragma once
// A rotor's Cp/Ct/Cq table over tip-speed ratio and collective pitch from the
// rigid rotor's steady BEM (yamsc/aero/rigid_rotor.hpp), as NREL's tools make
// it with AeroDyn, normalized as ROSCO reads it: the free wind speed U and the
// rotor radius R (ElastoDyn's TipRad), Cp = P / (rho/2 pi R^2 U^3), Ct = T /
// (rho/2 pi R^2 U^2) with T the thrust along the shaft, Cq = Q / (rho/2 pi R^3
// U^2), TSR = Omega R / U; each value the mean over azimuths of one blade
// passage (tilt and precone make the rotor's loads vary with azimuth).
#include <ostream>
#include <string>
#include <vector>

#include "yamsc/aero/rigid_rotor.hpp"
#include "yamsc/performance_table.hpp"

namespace yamsc::aero {

struct TableRequest {
    std::vector<double> tsr;       // rows, increasing [-]
    std::vector<double> pitch_deg; // columns, increasing [deg]
    double wind_speed = 11.4;      // [m/s]
    double rotor_radius = 63;      // R of the normalization [m]
    int azimuths = 6;              // samples over one blade passage (360 deg / blades)
};

runtime::PerformanceTable rotor_performance_table(const RotorInput& input,
                                                  const RotorGeometry& geometry,
                                                  const TableRequest& request);

// ROSCO's text format (Cp_Ct_Cq.<turbine>.txt), readable by
// runtime::read_performance_table; `title` goes into the first comment line.
void write_performance_table(std::ostream& out, const runtime::PerformanceTable& table,
                             double wind_speed, const std::string& title);

} // namespace yamsc::aero
