#include "formats/validate_kinds.h"

namespace kdpm {

// Filled in with the geometry layout: required sections, index ranges, tree invariants.
void validate_geometry_file(const ContainerReader&, const ValidationOptions&) {}

}  // namespace kdpm
