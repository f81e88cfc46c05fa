// SPDX-License-Identifier: MIT
#pragma once
/// Checkpoint files: the whole state of a run (Simulation::save_state and the RunRecord) in a
/// versioned binary file from which `fddem run --restart` continues bit for bit, on any number
/// of ranks.
///
/// A run on one process writes one file. A run on N ranks writes it in N pieces
/// (io/piece_archive.hpp, issue 15): every rank writes its own piece of the grid arrays, so no
/// rank holds the whole grid. Rank 0's piece, with everything that is not a grid array, is the
/// checkpoint's file; rank r's piece (r ≥ 1) is the file beside it with ".<w>.piece<r>" appended
/// (w: the write number, checkpoint_piece_path).
/// A restart on M ranks reads on each rank the file and the pieces its block overlaps.
///
/// Layout of the file (all integers little-endian):
///     "FDDEMCKP"                  8 bytes, magic
///     format version              8 bytes
///     header                      named values (checkpoint_archive.hpp): dimension, step, time,
///                                 fddem version, layout (grid and bodies), the case as run,
///                                 the pieces (each one's storage box, and the CRC-32 of its
///                                 file; the first piece is in this file)
///     state                       Simulation<Dim>::save_state (rank 0's piece), then
///                                 RunRecord::visit
///     length                      8 bytes: the number of bytes before it
///     CRC-32                      4 bytes, of every byte before it (zlib's crc32, ISO-HDLC)
/// Of a piece file: the magic, the format version, "piece" (its number) and "step", the rank's
/// piece of the grid arrays, and the same trailer.
///
/// Every file is written to a temporary name, synced and renamed (then its directory synced),
/// the pieces before the checkpoint's file, so a run killed at any moment leaves every earlier
/// checkpoint whole and a later one absent; a damaged or truncated file, or a piece of another
/// checkpoint, fails the length or CRC check and is refused with the reason.

#include "fddem/io/checkpoint_archive.hpp"
#include "fddem/io/checkpoint_frame.hpp"
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
// 8: the grid arrays in pieces, one per rank (the pieces' table in the header); 9: the count of
// the joint film solves stopped at an iteration limit (summary.json)
inline constexpr std::uint64_t checkpoint_format_version = 9;

/// (key, value as text) pairs: what a checkpoint's grid and bodies must share with the case it
/// is restored into.
using CheckpointLayout = std::vector<std::pair<std::string, std::string>>;

/// The layout of `sim`: dimension, domain.origin/size/cells/periodic, number of bodies and
/// markers of each. Values print in shortest round-trip form, so equal text is equal value.
template <int Dim>
[[nodiscard]] CheckpointLayout checkpoint_layout(const Simulation<Dim>& sim);

/// One rank's piece of a checkpoint: the storage box it covers, and the CRC-32 of the file that
/// holds it (0 for the first piece, which is in the checkpoint's file).
struct CheckpointPiece {
    std::vector<int> lo;
    std::vector<int> hi;
    std::uint32_t crc = 0;

    template <class Self, class Archive>
    static void visit(Self& piece, Archive& archive)
    {
        archive("piece.lo", piece.lo);
        archive("piece.hi", piece.hi);
        archive("piece.crc", piece.crc);
    }
};

/// What a checkpoint says about itself, readable before the state is restored.
struct CheckpointHeader {
    int dimension = 0;
    long step = 0;
    double time = 0.0; ///< [s]
    std::string fddem_version;
    CheckpointLayout layout;
    std::string case_text; ///< the case as run when the checkpoint was written (case.toml)
    std::vector<CheckpointPiece> pieces; ///< one per rank of the run that wrote it
    long pieces_write = 0;               ///< the write number in the pieces' file names
};

/// The file of piece `index` (≥ 1) of write number `write` of the checkpoint `path`: `path`
/// with ".<write>.piece<index>". The write number is new for every write at one path, so that
/// writing a checkpoint again (a step written again after a numerical failure rolled it back)
/// never overwrites a piece that the checkpoint's file still names.
[[nodiscard]] std::filesystem::path checkpoint_piece_path(const std::filesystem::path& path,
                                                          long write, int index);

/// The CRC-32 of `bytes` (zlib: a Debian library, and the check every zip/png reader uses).
[[nodiscard]] std::uint32_t crc32_of(std::string_view bytes);

/// Writes a checkpoint of `sim` and `record` to `path`, atomically and durably. On a split
/// grid every rank calls it (collective): each writes its piece, and rank 0 (whose `record` is
/// written) the checkpoint's file last. Throws OutputError; `path` is then untouched.
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
    /// throws CheckpointError if the state does not read back, or a piece that this rank's
    /// block overlaps is missing, damaged or of another checkpoint. On a split grid each rank
    /// calls it on its own (no communication); the caller must agree on the outcome.
    template <int Dim>
    void restore(Simulation<Dim>& sim, RunRecord& record) const;

private:
    /// The piece file `index` (≥ 1), checked (its frame, its CRC-32 against the pieces' table,
    /// its number and step) and opened for reading after its number and step. Throws
    /// CheckpointError.
    [[nodiscard]] FramedStream open_piece(std::size_t index) const;

    std::filesystem::path path_;
    std::string bytes_;
    CheckpointHeader header_;
    std::size_t state_offset_ = 0; ///< where the state starts in bytes_
    std::size_t state_end_ = 0;    ///< where the trailer starts
};

} // namespace fddem
