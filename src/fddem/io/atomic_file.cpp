// SPDX-License-Identifier: MIT
#include "fddem/io/atomic_file.hpp"

#include <cstdio>
#include <fcntl.h>
#include <string>
#include <system_error>
#include <unistd.h>

namespace fddem {

void write_file_atomically(const std::filesystem::path& path, std::string_view content)
{
    write_file_atomically(path, std::span<const std::string_view>(&content, 1));
}

void write_file_atomically(const std::filesystem::path& path,
                           std::span<const std::string_view> parts)
{
    std::filesystem::path temporary = path;
    temporary += ".tmp." + std::to_string(::getpid());
    std::FILE* file = std::fopen(temporary.c_str(), "wb");
    if (file == nullptr) {
        throw OutputError("cannot write " + temporary.string());
    }
    bool is_written = true;
    for (const std::string_view content : parts) {
        is_written =
            is_written && std::fwrite(content.data(), 1, content.size(), file) == content.size();
    }
    const bool is_flushed = std::fflush(file) == 0 && ::fsync(::fileno(file)) == 0;
    const bool is_closed = std::fclose(file) == 0;
    if (!is_written || !is_flushed || !is_closed) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw OutputError("cannot write " + path.string() + " (disk full?)");
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::filesystem::remove(temporary, error);
        throw OutputError("cannot rename " + temporary.string() + " to " + path.string());
    }
}

bool sync_directory(const std::filesystem::path& directory) noexcept
{
    const char* name = directory.empty() ? "." : directory.c_str();
    const int fd = ::open(name, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) {
        return false;
    }
    const bool is_synced = ::fsync(fd) == 0;
    ::close(fd);
    return is_synced;
}

} // namespace fddem
