// SPDX-License-Identifier: MIT
#include "fddem/io/checkpoint.hpp"

#include "fddem/core/errors.hpp"
#include "fddem/io/atomic_file.hpp"
#include "fddem/io/checkpoint_frame.hpp"
#include "fddem/io/piece_archive.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <string_view>
#include <system_error>

namespace fddem {
namespace {

template <class Values>
std::string list_text(const Values& values)
{
    std::string text = "[";
    for (std::size_t k = 0; k < values.size(); ++k) {
        text += fmt::format("{}{}", k == 0 ? "" : ", ", values[k]);
    }
    return text + "]";
}

/// The header's named values, for writing and reading alike.
template <class Header, class Archive>
void visit_header(Header& h, Archive& archive)
{
    archive("dimension", h.dimension);
    archive("step", h.step);
    archive("time", h.time);
    archive("fddem_version", h.fddem_version);
    archive("layout", h.layout);
    archive("case", h.case_text);
    archive("pieces", h.pieces);
    archive("pieces_write", h.pieces_write);
}

/// This rank's piece of `sim`'s state (io/piece_archive.hpp), with everything that is not a
/// grid array and then `record` on the first rank; in a string reserved once at its size.
template <int Dim>
std::string piece_state(const Simulation<Dim>& sim, bool is_first, const RunRecord& record)
{
    ArchiveWriter counter(ArchiveWriter::Counting{});
    PieceWriter<Dim> count(sim.grid(), counter, is_first);
    sim.save_state(count);
    ArchiveWriter state;
    if (is_first) {
        RunRecord::visit(record, counter);
    }
    state.bytes().reserve(counter.size());
    PieceWriter<Dim> writer(sim.grid(), state, is_first);
    sim.save_state(writer);
    if (is_first) {
        RunRecord::visit(record, state);
    }
    return std::move(state.bytes());
}

template <int Dim>
std::vector<int> box_bounds(const Box<Dim>& box, bool is_high)
{
    std::vector<int> bounds;
    for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
        bounds.push_back(is_high ? box.hi[d] : box.lo[d]);
    }
    return bounds;
}

template <int Dim>
Box<Dim> piece_box(const CheckpointPiece& piece)
{
    if (piece.lo.size() != static_cast<std::size_t>(Dim) ||
        piece.hi.size() != static_cast<std::size_t>(Dim)) {
        throw CheckpointError("has a piece whose box is not of the grid's dimension");
    }
    Box<Dim> box;
    for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
        box.lo[d] = piece.lo[d];
        box.hi[d] = piece.hi[d];
    }
    return box;
}

} // namespace

std::uint32_t crc32_of(std::string_view bytes)
{
    return continue_crc32(0, bytes);
}

template <int Dim>
CheckpointLayout checkpoint_layout(const Simulation<Dim>& sim)
{
    const MacGrid<Dim>& grid = sim.grid();
    std::vector<double> origin;
    std::vector<double> size;
    std::vector<int> cells;
    std::vector<std::string> periodic;
    for (int d = 0; d < Dim; ++d) {
        origin.push_back(grid.origin()[d]);
        size.push_back(grid.length()[d]);
        cells.push_back(grid.cells(d));
    }
    for (const bool is_periodic : sim.boundary_conditions().is_periodic) {
        periodic.emplace_back(is_periodic ? "true" : "false");
    }
    std::vector<std::size_t> markers;
    for (const Particle<Dim>& body : sim.bodies()) {
        markers.push_back(body.coupling.markers.size());
    }
    return {
        {"dimension", std::to_string(Dim)},       {"domain.origin", list_text(origin)},
        {"domain.size", list_text(size)},         {"domain.cells", list_text(cells)},
        {"domain.periodic", list_text(periodic)}, {"bodies", std::to_string(sim.bodies().size())},
        {"bodies.markers", list_text(markers)}};
}

namespace {

/// The write number w of a piece file named "<master>.<w>.piece<r>" (both numbers all digits),
/// none for any other name.
std::optional<long> piece_write_number(std::string_view name, std::string_view master)
{
    const auto is_number = [](std::string_view text) {
        return !text.empty() && text.size() < 18 &&
               std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
    };
    if (!name.starts_with(master) || name.size() <= master.size() || name[master.size()] != '.') {
        return std::nullopt;
    }
    const std::string_view rest = name.substr(master.size() + 1);
    const std::size_t at = rest.find(".piece");
    if (at == std::string_view::npos || !is_number(rest.substr(0, at)) ||
        !is_number(rest.substr(at + 6))) {
        return std::nullopt;
    }
    return std::stol(std::string(rest.substr(0, at)));
}

/// The write number of each piece file of the checkpoint `path` that is there, with its path.
std::vector<std::pair<long, std::filesystem::path>>
existing_pieces(const std::filesystem::path& path)
{
    std::vector<std::pair<long, std::filesystem::path>> pieces;
    const std::string master = path.filename().string();
    std::error_code error;
    for (const auto& file : std::filesystem::directory_iterator(path.parent_path(), error)) {
        if (const auto write = piece_write_number(file.path().filename().string(), master)) {
            pieces.emplace_back(*write, file.path());
        }
    }
    return pieces;
}

/// Rank 0's part of write_checkpoint: the checkpoint's file, with the header (and the pieces'
/// `table`, `width` values per rank, written as `write`) and its piece of the `state` (the
/// record included); then the pieces of earlier writes of this checkpoint are removed.
template <int Dim>
void write_first_piece(const std::filesystem::path& path, const Simulation<Dim>& sim,
                       const std::string& state, const std::vector<int>& table, std::size_t width,
                       long write)
{
    CheckpointHeader header;
    header.dimension = Dim;
    header.step = sim.clock().step;
    header.time = sim.clock().time;
    header.fddem_version = FDDEM_VERSION;
    header.layout = checkpoint_layout(sim);
    header.case_text = sim.config().as_run;
    header.pieces_write = write;
    for (std::size_t at = 0; at + width <= table.size(); at += width) {
        CheckpointPiece piece;
        piece.lo.assign(table.begin() + static_cast<std::ptrdiff_t>(at),
                        table.begin() + static_cast<std::ptrdiff_t>(at + Dim));
        piece.hi.assign(table.begin() + static_cast<std::ptrdiff_t>(at + Dim),
                        table.begin() + static_cast<std::ptrdiff_t>(at + 2 * Dim));
        piece.crc = static_cast<std::uint32_t>(table[at + 2 * Dim]);
        header.pieces.push_back(std::move(piece));
    }

    ArchiveWriter head;
    head.bytes() = frame_start(checkpoint_format_version);
    visit_header(header, head);
    write_framed(path, head.bytes(), state);
    static_cast<void>(sync_directory(path.parent_path())); // best effort (see there)
    // An earlier write of this checkpoint (a step written again after a numerical failure, or
    // by a run on more ranks) left pieces under another write number: no longer read.
    for (const auto& [number, piece] : existing_pieces(path)) {
        if (number != write) {
            std::error_code ignored;
            std::filesystem::remove(piece, ignored);
        }
    }
}

/// A write number for a new write of the checkpoint `path` that no piece file there has, the
/// same on every rank (rank 0 looks, and tells the others): a write at the same name never
/// touches the pieces the checkpoint's file there names until that file is replaced.
long next_write_number(const std::filesystem::path& path, const Communicator& ranks)
{
    std::string number;
    if (ranks.rank() == 0) {
        long largest = 0;
        for (const auto& [write, piece] : existing_pieces(path)) {
            largest = std::max(largest, write);
        }
        number = std::to_string(largest + 1);
    }
    ranks.broadcast(number);
    return std::stol(number);
}

} // namespace

std::filesystem::path checkpoint_piece_path(const std::filesystem::path& path, long write,
                                            int index)
{
    std::filesystem::path piece = path;
    piece += fmt::format(".{}.piece{}", write, index);
    return piece;
}

template <int Dim>
void write_checkpoint(const std::filesystem::path& path, const Simulation<Dim>& sim,
                      const RunRecord& record)
{
    const MacGrid<Dim>& grid = sim.grid();
    const Communicator& ranks = grid.communicator();
    const bool is_first = ranks.rank() == 0;
    const std::string state = piece_state(sim, is_first, record);
    const long write = next_write_number(path, ranks);

    // Every other rank writes its piece first, then tells rank 0 its box and CRC (the gather
    // also says that every piece is on disk before the checkpoint's file names it).
    std::uint32_t crc = 0;
    if (!is_first) {
        ArchiveWriter head;
        head.bytes() = frame_start(checkpoint_format_version);
        head("piece", static_cast<long>(ranks.rank()));
        head("step", sim.clock().step);
        crc = write_framed(checkpoint_piece_path(path, write, ranks.rank()), head.bytes(), state);
    }
    const Box<Dim> box = contributed_box(grid);
    std::vector<int> mine = box_bounds(box, false);
    for (const int high : box_bounds(box, true)) {
        mine.push_back(high);
    }
    mine.push_back(static_cast<int>(crc)); // the bits of the CRC-32
    const std::vector<int> all = ranks.all_gather(mine);
    if (is_first) {
        write_first_piece(path, sim, state, all, mine.size(), write);
    }
    // On return the checkpoint is whole for every rank (a rank that reads it at once, or a
    // failure on rank 0 that must not leave the others a checkpoint to find).
    static_cast<void>(ranks.max(0.0));
}

CheckpointFile::CheckpointFile(const std::filesystem::path& path) : path_(path)
{
    FramedBytes file = read_framed(path, checkpoint_format_version);
    bytes_ = std::move(file.bytes);
    state_end_ = file.check.content_end;
    ArchiveReader archive(std::string_view(bytes_).substr(0, state_end_));
    archive.get_u64(); // magic
    archive.get_u64(); // version
    visit_header(header_, archive);
    state_offset_ = archive.position();
    if (header_.pieces.empty()) {
        throw CheckpointError("lists no pieces of the grid");
    }
}

void CheckpointFile::check_layout(const CheckpointLayout& layout) const
{
    for (const auto& [key, value] : layout) {
        std::string stored = "(none)";
        for (const auto& [k, v] : header_.layout) {
            if (k == key) {
                stored = v;
            }
        }
        if (stored != value) {
            throw InputError(path_.string(), 0, key,
                             fmt::format("the checkpoint was written for {} = {}, the case has "
                                         "{}; a restart keeps the grid and the bodies",
                                         key, stored, value));
        }
    }
}

FramedStream CheckpointFile::open_piece(std::size_t index) const
{
    const std::filesystem::path piece_path =
        checkpoint_piece_path(path_, header_.pieces_write, static_cast<int>(index));
    FrameCheck check;
    try {
        check = check_framed(piece_path, checkpoint_format_version);
    } catch (const CheckpointError& e) {
        throw CheckpointError(
            fmt::format("has a piece, {}, that {}", piece_path.filename().string(), e.what()));
    }
    if (check.crc != header_.pieces[index].crc) {
        throw CheckpointError(fmt::format("has a piece, {}, of another checkpoint (CRC-32 {:08x}, "
                                          "the checkpoint records {:08x})",
                                          piece_path.filename().string(), check.crc,
                                          header_.pieces[index].crc));
    }
    FramedStream piece(piece_path, check);
    long number = 0;
    long step = 0;
    piece("piece", number);
    piece("step", step);
    if (number != static_cast<long>(index) || step != header_.step) {
        throw CheckpointError(fmt::format("has a piece, {}, that says it is piece {} of step {}",
                                          piece_path.filename().string(), number, step));
    }
    return piece;
}

template <int Dim>
void CheckpointFile::restore(Simulation<Dim>& sim, RunRecord& record) const
{
    check_layout(checkpoint_layout(sim));
    const MacGrid<Dim>& grid = sim.grid();
    const Box<Dim> storage = grid.storage_box();
    // The other pieces this rank's block overlaps, each checked whole first, then read one
    // array at a time (io/checkpoint_frame.hpp).
    std::vector<std::unique_ptr<FramedStream>> streams;
    std::vector<StatePiece<Dim>> others;
    for (std::size_t k = 1; k < header_.pieces.size(); ++k) {
        const Box<Dim> box = piece_box<Dim>(header_.pieces[k]);
        if (intersection(box, storage).size() == 0) {
            continue;
        }
        FramedStream* stream =
            streams.emplace_back(std::make_unique<FramedStream>(open_piece(k))).get();
        const std::string file =
            checkpoint_piece_path(path_, header_.pieces_write, static_cast<int>(k))
                .filename()
                .string();
        others.push_back({box, [stream, file](std::string_view name, std::vector<double>& values) {
                              try {
                                  (*stream)(name, values);
                              } catch (const CheckpointError& e) {
                                  throw CheckpointError(
                                      fmt::format("has a piece, {}, that {}", file, e.what()));
                              }
                          }});
    }

    ArchiveReader archive(std::string_view(bytes_).substr(0, state_end_));
    archive.get_u64();
    archive.get_u64();
    CheckpointHeader ignored;
    visit_header(ignored, archive);
    PieceReader<Dim> reader(grid, archive, piece_box<Dim>(header_.pieces.front()),
                            std::move(others));
    try {
        sim.load_state(reader);
    } catch (const InputError& e) {
        throw InputError(path_.string(), 0, e.key(), e.what());
    }
    RunRecord::visit(record, archive);
    if (!archive.is_at_end()) {
        throw CheckpointError(fmt::format("has {} bytes after the state (another fddem version?)",
                                          state_end_ - archive.position()));
    }
    for (const auto& stream : streams) {
        if (!stream->is_at_end()) {
            throw CheckpointError("has a piece with bytes after its grid arrays");
        }
    }
}

template CheckpointLayout checkpoint_layout<2>(const Simulation<2>&);
template CheckpointLayout checkpoint_layout<3>(const Simulation<3>&);
template void write_checkpoint<2>(const std::filesystem::path&, const Simulation<2>&,
                                  const RunRecord&);
template void write_checkpoint<3>(const std::filesystem::path&, const Simulation<3>&,
                                  const RunRecord&);
template void CheckpointFile::restore<2>(Simulation<2>&, RunRecord&) const;
template void CheckpointFile::restore<3>(Simulation<3>&, RunRecord&) const;

} // namespace fddem
