// SPDX-License-Identifier: MIT
#include "fddem/run/run_outputs.hpp"

#include "fddem/io/atomic_file.hpp"
#include "fddem/io/run_directory.hpp"
#include "fddem/run/body_snapshot.hpp"
#include "fddem/run/field_frames.hpp"
#include "fddem/run/paraview_script.hpp"
#include "fddem/run/particle_history.hpp"
#include "fddem/run/solver_history.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace fddem {
namespace {

namespace fs = std::filesystem;
using Frames = std::vector<std::pair<double, std::string>>;

/// The first `n_frames` entries of `pvd`.
Frames first_frames(const PvdCollection& pvd, std::size_t n_frames)
{
    const Frames& all = pvd.entries();
    return {all.begin(), all.begin() + static_cast<std::ptrdiff_t>(std::min(n_frames, all.size()))};
}

} // namespace

template <int Dim>
RunOutputs<Dim>::RunOutputs(fs::path directory, bool has_bodies)
    : directory_(std::move(directory)), has_bodies_(has_bodies),
      fields_pvd_(directory_ / "fields.pvd"), particles_pvd_(directory_ / "particles.pvd")
{
}

template <int Dim>
void RunOutputs<Dim>::create()
{
    write_file_atomically(directory_ / paraview_script_name, paraview_script);
    solver_ = std::make_unique<CsvHistory>(directory_ / "solver.csv", solver_columns());
    if (has_bodies_) {
        particles_ =
            std::make_unique<CsvHistory>(directory_ / "particles.csv", particle_columns<Dim>());
    }
}

template <int Dim>
void RunOutputs<Dim>::check(const RunRecord& record) const
{
    check_history(directory_ / "solver.csv", solver_columns(), record.solver_csv_bytes);
    if (has_bodies_) {
        check_history(directory_ / "particles.csv", particle_columns<Dim>(),
                      record.particles_csv_bytes);
    }
}

template <int Dim>
void RunOutputs<Dim>::continue_from(const RunRecord& record)
{
    const fs::path solver_path = directory_ / "solver.csv";
    truncate_history(solver_path, record.solver_csv_bytes);
    solver_ = std::make_unique<CsvHistory>(solver_path, solver_columns(), CsvHistory::Continue{});
    fields_pvd_.assign(record.field_frames);
    remove_unlisted_files(directory_, "fields", {".vtr", ".pvtr"}, record.field_frames);
    if (has_bodies_) {
        const fs::path particles_path = directory_ / "particles.csv";
        truncate_history(particles_path, record.particles_csv_bytes);
        particles_ = std::make_unique<CsvHistory>(particles_path, particle_columns<Dim>(),
                                                  CsvHistory::Continue{});
        particles_pvd_.assign(record.particle_frames);
        remove_unlisted_files(directory_, "particles", {".vtp", ".pvtp"}, record.particle_frames);
    }
}

template <int Dim>
void RunOutputs<Dim>::append_step(const Clock& clock, const StepReport& report,
                                  long total_outer_iterations, double wall_seconds)
{
    append_solver_row(*solver_, clock, report, total_outer_iterations, wall_seconds);
}

template <int Dim>
void RunOutputs<Dim>::append_particles(const Simulation<Dim>& sim)
{
    const std::vector<BodySnapshot<Dim>> bodies = body_snapshots(sim);
    append_particle_rows<Dim>(*particles_, sim.clock().time, bodies);
}

template <int Dim>
void RunOutputs<Dim>::write_frame(const Simulation<Dim>& sim)
{
    fddem::write_frame(sim, directory_, fields_pvd_, particles_pvd_);
}

template <int Dim>
bool RunOutputs<Dim>::has_frame_at(double time) const noexcept
{
    return !fields_pvd_.entries().empty() && fields_pvd_.entries().back().first >= time;
}

template <int Dim>
void RunOutputs<Dim>::record_lengths(RunRecord& record, std::size_t n_frames)
{
    record.field_frames = first_frames(fields_pvd_, n_frames);
    record.particle_frames = first_frames(particles_pvd_, n_frames);
    solver_->sync();
    record.solver_csv_bytes = solver_->size();
    if (particles_) {
        particles_->sync();
        record.particles_csv_bytes = particles_->size();
    }
}

template class RunOutputs<2>;
template class RunOutputs<3>;

} // namespace fddem
