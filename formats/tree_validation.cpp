#include "formats/tree_validation.h"

#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <system_error>
#include <thread>
#include <vector>

#include "formats/validate_kinds.h"

namespace kdpm {
namespace {

// Below this size a second thread costs more than it saves (the fuzzer's inputs, test files).
constexpr std::size_t kConcurrentChecksBytes = std::size_t{1} << 20;

// The kind's structural passes, in the order their failures are reported.
std::vector<std::function<void()>> passes_of(const ContainerReader& file, const ValidationOptions& options) {
    switch (file.kind()) {
        case FileKind::geometry: return {[&] { validate_geometry_file(file, options); }};
        case FileKind::photon_hits: return {[&] { validate_photon_hits_file(file, options); }};
        case FileKind::photon_tree: return photon_tree_passes(file, options);
        case FileKind::test: break;
    }
    return {};
}

}  // namespace

// Every load pays the checksums and the structural passes. On a large file a second thread
// computes the checksums and then takes structural passes from the back of the list while this
// thread takes them from the front (all only read the mapping; the structural checks take any
// bytes, as a forged checksum could bring them). Failures are reported as when everything ran
// one after the other: a checksum first, then the first failing pass in list order.
void validate_file(const ContainerReader& file, const ValidationOptions& options) {
    const std::vector<std::function<void()>> passes = passes_of(file, options);
    std::vector<std::exception_ptr> errors(passes.size());
    std::exception_ptr checksum_error;
    std::mutex claim_mutex;
    std::size_t front = 0, back = passes.size();  // passes [front, back) are not yet claimed
    auto claim = [&](bool from_back) -> std::optional<std::size_t> {
        std::lock_guard<std::mutex> lock(claim_mutex);
        if (front == back) return std::nullopt;
        return from_back ? --back : front++;
    };
    auto run_claimed = [&](bool from_back) {
        while (const std::optional<std::size_t> i = claim(from_back)) {
            try {
                passes[*i]();
            } catch (...) {
                errors[*i] = std::current_exception();
            }
        }
    };
    std::thread helper;
    if (file.file_bytes().size() >= kConcurrentChecksBytes) {
        try {
            helper = std::thread([&] {
                try {
                    file.verify();
                } catch (...) {
                    checksum_error = std::current_exception();
                }
                run_claimed(true);
            });
        } catch (const std::system_error&) {
            // No thread to be had: one after the other.
        }
    }
    if (!helper.joinable()) file.verify();
    run_claimed(false);
    if (helper.joinable()) helper.join();
    if (checksum_error) std::rethrow_exception(checksum_error);
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);
}

}  // namespace kdpm
