// SPDX-License-Identifier: MIT
#pragma once
/// Checkpoint files: the whole state of a run (Simulation::save_state and the RunRecord) in a
/// versioned binary file from which `fddem run --restart` continues bit for bit.
///
/// Layout (all integers little-endian):
///     "FDDEMCKP"                  8 bytes, magic
///     format version              8 bytes
///     header                      named values (checkpoint_archive.hpp): dimension, step, time,
///                                 fddem version, layout (grid and bodies), the case as run
///     state                       Simulation<Dim>::save_state, then RunRecord::visit
///     length                      8 bytes: the number of bytes before it
///     CRC-32                      4 bytes, of every byte before it (zlib's crc32, ISO-HDLC)
/// A file is written to a temporary name, synced and renamed (then its directory synced), so a
/// run killed at any moment leaves every earlier checkpoint whole; a damaged or truncated file
/// fails the length or CRC check and is refused with the reason.

#include "fddem/io/checkpoint_archive.hpp"
#include "fddem/io/run_record.hpp"
#include "fddem/simulation/simulation.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace fddem {

/// The format version written; only this one is read (a new state member bumps it).
// 2: springs; 3: rest_since; 4: the adaptive time step's residual history; 5: the per-contact
// constants of the adaptive collision model; 6: the last step's Δt and each body's U^{n−1},
// ω^{n−1} (time.scheme = "bdf2"); 7: the collisions under way (lubrication.coupling = "implicit")
inline constexpr std::uint64_t checkpoint_format_version = 7;

/// (key, value as text) pairs: what a checkpoint's grid and bodies must share with the case it
/// is restored into.
using CheckpointLayout = std::vector<std::pair<std::string, std::string>>;

/// The layout of `sim`: dimension, domain.origin/size/cells/periodic, number of bodies and
/// markers of each. Values print in shortest round-trip form, so equal text is equal value.
template <int Dim>
[[nodiscard]] CheckpointLayout checkpoint_layout(const Simulation<Dim>& sim);

/// What a checkpoint says about itself, readable before the state is restored.
struct CheckpointHeader {
    int dimension = 0;
    long step = 0;
    double time = 0.0; ///< [s]
    std::string fddem_version;
    CheckpointLayout layout;
    std::string case_text; ///< the case as run when the checkpoint was written (case.toml)
};

/// The CRC-32 of `bytes` (zlib: a Debian library, and the check every zip/png reader uses).
[[nodiscard]] std::uint32_t crc32_of(std::string_view bytes);

/// Writes a checkpoint of `sim` and `record` to `path`, atomically and durably. Throws
/// OutputError; `path` is then untouched.
template <int Dim>
void write_checkpoint(const std::filesystem::path& path, const Simulation<Dim>& sim,
                      const RunRecord& record);

/// A checkpoint file read whole and verified (magic, format version, length, CRC-32).
class CheckpointFile {
public:
    /// Throws CheckpointError with the reason if the file is missing, damaged or truncated,
    /// not a checkpoint, or of another format version.
    explicit CheckpointFile(const std::filesystem::path& path);

    [[nodiscard]] const std::filesystem::path& path() const noexcept { return path_; }
    [[nodiscard]] const CheckpointHeader& header() const noexcept { return header_; }

    /// Throws InputError naming the first key whose value differs between the checkpoint's
    /// layout and `layout` (a checkpoint of another case or grid).
    void check_layout(const CheckpointLayout& layout) const;

    /// Restores `sim` (built from the case) and `record`. Checks the layout first (InputError);
    /// throws CheckpointError if the state does not read back.
    template <int Dim>
    void restore(Simulation<Dim>& sim, RunRecord& record) const;

private:
    std::filesystem::path path_;
    std::string bytes_;
    CheckpointHeader header_;
    std::size_t state_offset_ = 0; ///< where the state starts in bytes_
    std::size_t state_end_ = 0;    ///< where the trailer starts
};

} // namespace fddem
