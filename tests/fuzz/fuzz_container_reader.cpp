// Feeds arbitrary bytes to the container reader and the structural validators: any crash,
// hang or sanitizer report is a bug. KDPM_FUZZ_SEED=DIR writes a valid seed file and exits.
#include <cstdint>
#include <cstdlib>
#include <fstream>

#include "formats/container_reader.h"
#include "formats/tree_validation.h"
#include "tests/formats/sample_container.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    if (const char* dir = std::getenv("KDPM_FUZZ_SEED")) {
        auto bytes = kdpm::test::sample_writer().bytes();
        std::ofstream(std::string(dir) + "/seed.kdt", std::ios::binary)
            .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
        std::exit(0);
    }
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        auto r = kdpm::ContainerReader::from_bytes({data, size}, "fuzz");
        kdpm::validate_file(r, {true});
        (void)r.metadata();
    } catch (const kdpm::FormatError&) {
    }
    return 0;
}
