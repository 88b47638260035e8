// SPDX-License-Identifier: MIT
// probes.csv of a run (docs/formats.md, LS-DYNA's nodout): for each [[probe]] particle, its
// fields at every history.csv row. The columns are time, step, then <probe>_<field> for every
// probe and every entry of kProbeFields (probes.cpp: adding a field is one line there and one
// in docs/formats.md). Written as a CsvTable (csv_table.hpp).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "case_config.hpp"
#include "csv_table.hpp"
#include "distributed/domain.hpp"
#include "particles/reference.hpp"
#include "particles/state.hpp"

namespace gsph::solver {

/// A probe: its name and the particle it follows.
struct Probe {
    std::string name;
    Index particle = 0;
    double distance = 0.0;  ///< from the [[probe]] point to the particle's X [m] (0 by index)
};

/// The particle of each [[probe]]: by index, or the nearest to its point in the reference
/// configuration (among the particles of its body, if it names one of `file`'s: namesBody).
/// Throws InputError "CASE:LINE: ..." for an index beyond the particles or an unknown body.
std::vector<Probe> findProbes(const CaseConfig& c, const Reference& ref, const ParticleFile& file);

class Probes {
  public:
    Probes(std::filesystem::path path, std::vector<Probe> probes);
    bool empty() const { return probes_.empty(); }
    const std::vector<Probe>& probes() const { return probes_; }
    /// The column names, in the file's order.
    std::vector<std::string> columnNames() const;
    /// A row of every probe's fields at the state. `owned`: the particles whose state is
    /// current here; in a split run (`domain` not null; collective) each probe's fields are
    /// read where its particle is owned and reach every process through the exact minimum (the
    /// other processes offer +∞), so no gather of the state is needed.
    void add(const Reference& ref, const State& state, ParticleRange owned,
             Domain* domain = nullptr);
    CsvTable& table() { return table_; }
    const CsvTable& table() const { return table_; }

  private:
    std::vector<Probe> probes_;
    CsvTable table_;
    std::vector<double> values_;  ///< a row's values, probe by probe and field by field
};

}  // namespace gsph::solver
