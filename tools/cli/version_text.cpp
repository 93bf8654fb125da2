#include "tools/cli/version_text.h"

#include "formats/file_kind.h"
#include "formats/metadata.h"

namespace kdpm::cli {

std::string version_text(const std::string& program) {
    std::string text = program + " (kdpm) " + kdpm_version() + "\nfile formats:";
    for (FileKind kind : {FileKind::geometry, FileKind::photon_hits, FileKind::photon_tree}) {
        const FileKindInfo& info = file_kind_info(kind);
        text += std::string(kind == FileKind::geometry ? " " : ", ") + std::string(info.extension) + " " +
                std::to_string(info.major) + "." + std::to_string(info.minor);
    }
#if KDPM_CUDA_BACKEND_BUILT
    text += "\nCUDA backend: built (used when a device is present)\n";
#else
    text += "\nCUDA backend: not built (CPU backend only)\n";
#endif
    return text;
}

}  // namespace kdpm::cli
