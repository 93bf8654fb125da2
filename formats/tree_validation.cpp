#include "formats/tree_validation.h"

#include <exception>
#include <system_error>
#include <thread>

#include "formats/validate_kinds.h"

namespace kdpm {
namespace {

// Below this size a second thread costs more than it saves (the fuzzer's inputs, test files).
constexpr std::size_t kConcurrentChecksBytes = std::size_t{1} << 20;

void validate_kind(const ContainerReader& file, const ValidationOptions& options) {
    switch (file.kind()) {
        case FileKind::geometry: validate_geometry_file(file, options); break;
        case FileKind::photon_hits: validate_photon_hits_file(file, options); break;
        case FileKind::photon_tree: validate_photon_tree_file(file, options); break;
        case FileKind::test: break;
    }
}

}  // namespace

// Every load pays both passes: on a large file the checksums run on a second thread while this
// one checks the structure (both only read the mapping; the structural checks take any bytes, as
// a forged checksum could bring them). A checksum failure is reported first, as it was when the
// passes ran one after the other.
void validate_file(const ContainerReader& file, const ValidationOptions& options) {
    std::exception_ptr checksum_error, kind_error;
    std::thread sums;
    if (file.file_bytes().size() >= kConcurrentChecksBytes) {
        try {
            sums = std::thread([&] {
                try {
                    file.verify();
                } catch (...) {
                    checksum_error = std::current_exception();
                }
            });
        } catch (const std::system_error&) {
            // No thread to be had: one after the other.
        }
    }
    if (!sums.joinable()) file.verify();
    try {
        validate_kind(file, options);
    } catch (...) {
        kind_error = std::current_exception();
    }
    if (sums.joinable()) sums.join();
    if (checksum_error) std::rethrow_exception(checksum_error);
    if (kind_error) std::rethrow_exception(kind_error);
}

}  // namespace kdpm
