// SPDX-License-Identifier: MIT
#include "fddem/io/checkpoint.hpp"

#include "fddem/core/errors.hpp"
#include "fddem/io/atomic_file.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <zlib.h>

namespace fddem {
namespace {

constexpr std::string_view magic = "FDDEMCKP";
constexpr std::size_t trailer_bytes = 8 + 4; ///< length and CRC-32

template <class Values>
std::string list_text(const Values& values)
{
    std::string text = "[";
    for (std::size_t k = 0; k < values.size(); ++k) {
        text += fmt::format("{}{}", k == 0 ? "" : ", ", values[k]);
    }
    return text + "]";
}

void put_u32(std::string& bytes, std::uint32_t value)
{
    for (int k = 0; k < 4; ++k) {
        bytes.push_back(static_cast<char>((value >> (8 * k)) & 0xffU));
    }
}

std::uint64_t get_le(std::string_view bytes, std::size_t at, int n)
{
    std::uint64_t value = 0;
    for (int k = 0; k < n; ++k) {
        value |= static_cast<std::uint64_t>(
                     static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(k)]))
                 << (8 * k);
    }
    return value;
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
}

} // namespace

std::uint32_t crc32_of(std::string_view bytes)
{
    // zlib takes bytes as unsigned char; reading a char buffer through it is well defined.
    const auto* data = reinterpret_cast<const Bytef*>( // NOLINT(*-reinterpret-cast)
        bytes.data());
    return static_cast<std::uint32_t>(crc32_z(crc32_z(0L, Z_NULL, 0), data, bytes.size()));
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

template <int Dim>
void write_checkpoint(const std::filesystem::path& path, const Simulation<Dim>& sim,
                      const RunRecord& record)
{
    CheckpointHeader header;
    header.dimension = Dim;
    header.step = sim.clock().step;
    header.time = sim.clock().time;
    header.fddem_version = FDDEM_VERSION;
    header.layout = checkpoint_layout(sim);
    header.case_text = sim.config().as_run;

    ArchiveWriter archive;
    archive.bytes() = magic;
    archive.put_u64(checkpoint_format_version);
    visit_header(header, archive);
    sim.save_state(archive);
    RunRecord::visit(record, archive);
    std::string& bytes = archive.bytes();
    archive.put_u64(bytes.size());
    put_u32(bytes, crc32_of(bytes));
    write_file_atomically(path, bytes);
    static_cast<void>(sync_directory(path.parent_path())); // best effort (see there)
}

CheckpointFile::CheckpointFile(const std::filesystem::path& path) : path_(path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw CheckpointError("cannot be opened");
    }
    std::ostringstream text;
    text << in.rdbuf();
    bytes_ = std::move(text).str();
    const std::string_view bytes = bytes_;
    if (bytes.size() < magic.size() + 8 + trailer_bytes) {
        throw CheckpointError(
            fmt::format("is truncated ({} bytes; not even a header and a trailer)", bytes.size()));
    }
    if (bytes.substr(0, magic.size()) != magic) {
        throw CheckpointError("is not an fddem checkpoint (no FDDEMCKP magic number)");
    }
    const std::uint64_t version = get_le(bytes, magic.size(), 8);
    if (version != checkpoint_format_version) {
        throw CheckpointError(fmt::format("has format version {}; this fddem reads version {}",
                                          version, checkpoint_format_version));
    }
    state_end_ = bytes.size() - trailer_bytes;
    const std::uint64_t length = get_le(bytes, state_end_, 8);
    if (length != state_end_) {
        throw CheckpointError(
            fmt::format("is truncated or damaged ({} bytes; its trailer expects {})", bytes.size(),
                        length + trailer_bytes));
    }
    const auto stored_crc = static_cast<std::uint32_t>(get_le(bytes, state_end_ + 8, 4));
    const std::uint32_t crc = crc32_of(bytes.substr(0, state_end_ + 8));
    if (crc != stored_crc) {
        throw CheckpointError(
            fmt::format("is damaged (CRC-32 {:08x}, the file records {:08x})", crc, stored_crc));
    }
    ArchiveReader archive(bytes.substr(0, state_end_));
    archive.get_u64(); // magic
    archive.get_u64(); // version
    visit_header(header_, archive);
    state_offset_ = archive.position();
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

template <int Dim>
void CheckpointFile::restore(Simulation<Dim>& sim, RunRecord& record) const
{
    check_layout(checkpoint_layout(sim));
    ArchiveReader archive(std::string_view(bytes_).substr(0, state_end_));
    archive.get_u64();
    archive.get_u64();
    CheckpointHeader ignored;
    visit_header(ignored, archive);
    try {
        sim.load_state(archive);
    } catch (const InputError& e) {
        throw InputError(path_.string(), 0, e.key(), e.what());
    }
    RunRecord::visit(record, archive);
    if (!archive.is_at_end()) {
        throw CheckpointError(fmt::format("has {} bytes after the state (another fddem version?)",
                                          state_end_ - archive.position()));
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
