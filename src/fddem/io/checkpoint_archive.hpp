// SPDX-License-Identifier: MIT
#pragma once
/// The encoding of checkpoint contents: a sequence of named values, each written and read by
/// one call `archive(name, value)`. The same call list serves both directions (the state's
/// owner writes it once, as Simulation::visit_state does), so writing and reading cannot drift
/// apart; the name stored before each value turns any drift into a clear error instead of a
/// silently shifted state.
///
/// Encoding: name as a 1-byte length and its characters; integers and booleans as 8-byte
/// little-endian two's complement; doubles as their 8-byte IEEE-754 bit pattern, little-endian
/// (exact, independent of the host's byte order); containers as an 8-byte count and their
/// elements. Supported values: arithmetic types, std::string, Eigen fixed-size vectors,
/// GridArray and FaceField, std::array, std::vector, std::pair and std::map of supported values,
/// and structs that list their members in a `static void visit(Self&, Archive&)` (as RunRecord
/// does; e.g. a per-pair contact history: a std::vector of such structs is then one line).

#include "fddem/grid/fields.hpp"

#include <Eigen/Core>

#include <array>
#include <bit>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace fddem {

/// A checkpoint that cannot be used: damaged, truncated, not a checkpoint, or of another
/// format version. A restart then tries the previous checkpoint.
class CheckpointError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// A struct that lists its members for an archive (see the file comment).
template <class T, class Archive>
concept ArchiveVisitable = requires(T& value, Archive& archive)
{
    T::visit(value, archive);
};

/// Appends named values to a byte string; or, made `counting`, only counts the bytes it would
/// append (to reserve a large archive's string once: grown by doubling, it would hold up to
/// three times its size while it grows).
class ArchiveWriter {
public:
    static constexpr bool is_reading = false;
    struct Counting {};

    ArchiveWriter() = default;
    explicit ArchiveWriter(Counting) : is_counting_(true) {}

    template <class T>
    void operator()(std::string_view name, const T& value)
    {
        put_name(name);
        put(value);
    }

    [[nodiscard]] const std::string& bytes() const noexcept { return bytes_; }
    [[nodiscard]] std::string& bytes() noexcept { return bytes_; }
    /// The bytes written (or counted) so far.
    [[nodiscard]] std::size_t size() const noexcept
    {
        return is_counting_ ? counted_ : bytes_.size();
    }

    void put_u64(std::uint64_t value)
    {
        if (is_counting_) {
            counted_ += 8;
            return;
        }
        for (int k = 0; k < 8; ++k) {
            bytes_.push_back(static_cast<char>((value >> (8 * k)) & 0xffU));
        }
    }

private:
    void put_name(std::string_view name);

    void put(double value) { put_u64(std::bit_cast<std::uint64_t>(value)); }
    void put(bool value) { put_u64(value ? 1U : 0U); }
    template <class T>
    requires std::is_integral_v<T>
    void put(T value) { put_u64(static_cast<std::uint64_t>(static_cast<std::int64_t>(value))); }
    void put(const std::string& text)
    {
        put_u64(text.size());
        append(text);
    }
    void append(std::string_view text)
    {
        if (is_counting_) {
            counted_ += text.size();
        } else {
            bytes_.append(text);
        }
    }
    template <int Rows>
    void put(const Eigen::Matrix<double, Rows, 1>& vector)
    {
        for (int k = 0; k < Rows; ++k) {
            put(vector[k]);
        }
    }
    template <int Dim>
    void put(const GridArray<Dim>& array)
    {
        put_u64(array.size());
        for (const double value : array.values()) {
            put(value);
        }
    }
    template <int Dim>
    void put(const FaceField<Dim>& field)
    {
        put(field.component);
    }
    template <class T, std::size_t N>
    void put(const std::array<T, N>& values)
    {
        for (const T& value : values) {
            put(value);
        }
    }
    template <class T>
    void put(const std::vector<T>& values)
    {
        put_u64(values.size());
        for (const auto& value : values) {
            put(static_cast<const T&>(value));
        }
    }
    template <class A, class B>
    void put(const std::pair<A, B>& pair)
    {
        put(pair.first);
        put(pair.second);
    }
    template <class K, class V>
    void put(const std::map<K, V>& map)
    {
        put_u64(map.size());
        for (const auto& [key, value] : map) {
            put(key);
            put(value);
        }
    }
    template <class T>
    requires ArchiveVisitable<const T, ArchiveWriter>
    void put(const T& value) { T::visit(value, *this); }

    std::string bytes_;
    bool is_counting_ = false;
    std::size_t counted_ = 0;
};

/// Reads named values back, in the order they were written. Throws CheckpointError when a
/// name, a size or the end of the data does not match what the caller expects.
class ArchiveReader {
public:
    static constexpr bool is_reading = true;

    explicit ArchiveReader(std::string_view bytes) : bytes_(bytes) {}

    template <class T>
    void operator()(std::string_view name, T& value)
    {
        expect_name(name);
        get(value);
    }

    [[nodiscard]] bool is_at_end() const noexcept { return position_ == bytes_.size(); }
    [[nodiscard]] std::size_t position() const noexcept { return position_; }

    std::uint64_t get_u64();

private:
    void expect_name(std::string_view name);
    /// A count of elements that must still fit in the data (each at least `element_bytes`).
    std::size_t get_count(std::size_t element_bytes);

    void get(double& value) { value = std::bit_cast<double>(get_u64()); }
    void get(bool& value) { value = get_u64() != 0; }
    template <class T>
    requires std::is_integral_v<T>
    void get(T& value)
    {
        const auto stored = static_cast<std::int64_t>(get_u64());
        if (!std::in_range<T>(stored)) {
            fail("an integer out of range");
        }
        value = static_cast<T>(stored);
    }
    void get(std::string& text)
    {
        const std::size_t n = get_count(1);
        text.assign(bytes_.substr(position_, n));
        position_ += n;
    }
    template <int Rows>
    void get(Eigen::Matrix<double, Rows, 1>& vector)
    {
        for (int k = 0; k < Rows; ++k) {
            get(vector[k]);
        }
    }
    template <int Dim>
    void get(GridArray<Dim>& array)
    {
        const std::size_t n = get_count(8);
        if (n != array.size()) {
            fail("a field of " + std::to_string(n) + " values where the grid has " +
                 std::to_string(array.size()));
        }
        for (double& value : array.values()) {
            get(value);
        }
    }
    template <int Dim>
    void get(FaceField<Dim>& field)
    {
        get(field.component);
    }
    template <class T, std::size_t N>
    void get(std::array<T, N>& values)
    {
        for (T& value : values) {
            get(value);
        }
    }
    template <class T>
    void get(std::vector<T>& values)
    {
        values.resize(get_count(1));
        for (std::size_t k = 0; k < values.size(); ++k) {
            T value{};
            get(value);
            values[k] = std::move(value);
        }
    }
    template <class A, class B>
    void get(std::pair<A, B>& pair)
    {
        get(pair.first);
        get(pair.second);
    }
    template <class K, class V>
    void get(std::map<K, V>& map)
    {
        map.clear();
        const std::size_t n = get_count(2);
        for (std::size_t k = 0; k < n; ++k) {
            K key{};
            V value{};
            get(key);
            get(value);
            map.emplace(std::move(key), std::move(value));
        }
    }
    template <class T>
    requires ArchiveVisitable<T, ArchiveReader>
    void get(T& value) { T::visit(value, *this); }
    [[noreturn]] void fail(const std::string& what) const;

    std::string_view bytes_;
    std::size_t position_ = 0;
    std::string current_name_; ///< for messages
};

} // namespace fddem
