// SPDX-License-Identifier: MIT
#pragma once
/// The files a run keeps adding to: solver.csv, particles.csv (with bodies), and the frames of
/// fields.pvd and particles.pvd. A new run creates them; a restarted one cuts them back to what
/// its checkpoint recorded and continues them.

#include "fddem/io/csv_history.hpp"
#include "fddem/io/run_record.hpp"
#include "fddem/io/vtk_writer.hpp"
#include "fddem/simulation/simulation.hpp"

#include <cstddef>
#include <filesystem>
#include <memory>

namespace fddem {

template <int Dim>
class RunOutputs {
public:
    RunOutputs(std::filesystem::path directory, bool has_bodies);

    /// A new run: the histories with their header lines (replacing those of a forced rerun), and
    /// the ParaView script open_in_paraview.py.
    void create();
    /// A restart, before anything is written: throws InputError (naming the file) unless each
    /// history starts with its header and can be cut back to the length `record` gives.
    void check(const RunRecord& record) const;
    /// A restart: cuts the histories back to `record`'s lengths, the frames to its lists
    /// (removing the files of later ones), and continues them.
    void continue_from(const RunRecord& record);

    void append_step(const Clock& clock, const StepReport& report, long total_outer_iterations,
                     double wall_seconds);
    /// particles.csv: the bodies of `sim` now. Only with bodies.
    void append_particles(const Simulation<Dim>& sim);
    /// The next field frame (and particles frame, with bodies). On a split grid every rank calls
    /// it and writes its pieces (run/field_frames.hpp); the collections are rank 0's.
    void write_frame(const Simulation<Dim>& sim);

    [[nodiscard]] bool has_bodies() const noexcept { return has_bodies_; }
    [[nodiscard]] std::size_t n_frames() const noexcept { return fields_pvd_.entries().size(); }
    /// Whether the last frame is of simulated time `time` or later.
    [[nodiscard]] bool has_frame_at(double time) const noexcept;

    /// Into `record` for a checkpoint: the histories' lengths, after syncing them to the disk
    /// (the rows reach it before a checkpoint that counts them does), and the first `n_frames`
    /// frames of each collection.
    void record_lengths(RunRecord& record, std::size_t n_frames);

private:
    std::filesystem::path directory_;
    bool has_bodies_;
    PvdCollection fields_pvd_;
    PvdCollection particles_pvd_;
    std::unique_ptr<CsvHistory> solver_;
    std::unique_ptr<CsvHistory> particles_;
};

} // namespace fddem
