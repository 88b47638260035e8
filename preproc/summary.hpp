// SPDX-License-Identifier: MIT
// The short report gsph-preproc prints on stdout: particles per space and per body, the
// physical spacing range (min/max hex edge), the particle sets and their sizes, how the blocks
// glued, and the time each phase took. Text for people; nothing parses it.
#pragma once

#include <ostream>
#include <string>

#include "conversion.hpp"
#include "io/particle_file.hpp"

namespace gsph::preproc {

struct Timings {
    double read = 0.0;     ///< gmsh: open (+ mesh a .geo) and copy out [s]
    double convert = 0.0;  ///< index, glue, geometry, sets [s]
    double write = 0.0;    ///< hash the input, write the HDF5 file [s]
    double total = 0.0;    ///< wall time of the whole run [s]
};

/// The first part, printed as soon as the blocks are glued (before hole cutting and transients,
/// whose errors name the spaces): the header, the particles per space with their gmsh volumes
/// and body.
void printSpaces(std::ostream& out, const std::string& input, const std::string& parameters,
                 const std::string& output, const ParticleFile& particles,
                 const ConversionStats& stats);

/// The rest, once the file is written: bodies, spacing, sets, metric, overset, gluing, timings.
void printSummary(std::ostream& out, const ParticleFile& particles, const ConversionStats& stats,
                  const Timings& timings);

}  // namespace gsph::preproc
