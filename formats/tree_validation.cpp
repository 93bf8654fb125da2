#include "formats/tree_validation.h"

#include "formats/validate_kinds.h"

namespace kdpm {

void validate_file(const ContainerReader& file, const ValidationOptions& options) {
    file.verify();
    switch (file.kind()) {
        case FileKind::geometry: validate_geometry_file(file, options); break;
        case FileKind::photon_hits: validate_photon_hits_file(file, options); break;
        case FileKind::photon_tree: validate_photon_tree_file(file, options); break;
        case FileKind::test: break;
    }
}

}  // namespace kdpm
