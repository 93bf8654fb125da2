// hash_file (the source_hash of every tool's metadata) is checksum64 of the whole file, read from a
// regular file or a pipe (in blocks); a file that cannot be read is a FormatError.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <cstdio>
#include <fstream>
#include <thread>
#include <vector>

#include "formats/checksum.h"
#include "formats/format_error.h"
#include "formats/metadata.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;

TEST_CASE("hash_file is the checksum of every byte of the file", "[formats]") {
    test::TempDir dir;
    for (std::size_t size : {std::size_t{0}, std::size_t{7}, std::size_t{65536}, (std::size_t{3} << 20) + 4097}) {
        std::vector<char> bytes(size);
        for (std::size_t i = 0; i < size; ++i) bytes[i] = static_cast<char>((i * 2654435761u) >> 13);
        const auto path = (dir / std::to_string(size)).string();
        std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        char hex[17];
        std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(checksum64(bytes.data(), bytes.size())));
        INFO("size " << size);
        CHECK(hash_file(path) == hex);
        if (size > 0) {
            bytes.back() ^= 1;  // the last byte counts too
            std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
            CHECK(hash_file(path) != hex);
        }
    }
    CHECK_THROWS_AS(hash_file((dir / "missing").string()), FormatError);
}

TEST_CASE("hash_file reads a pipe, whose size is unknown, to its end", "[formats]") {
    std::vector<char> bytes(200000);
    for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>(i * 7 + (i >> 9));
    test::TempDir dir;
    const auto source = (dir / "source").string();
    std::ofstream(source, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    const auto fifo = (dir / "fifo").string();
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    // A writer on the other end: the open of the FIFO for reading waits for it.
    std::thread writer([&] { std::ofstream(fifo, std::ios::binary) << std::ifstream(source, std::ios::binary).rdbuf(); });
    const std::string hashed = hash_file(fifo);
    writer.join();
    CHECK(hashed == hash_file(source));
}
