#include "formats/validate_kinds.h"

namespace kdpm {

// Filled in with the photon_tree layout: required sections, index ranges, tree invariants.
void validate_photon_tree_file(const ContainerReader&, const ValidationOptions&) {}

}  // namespace kdpm
