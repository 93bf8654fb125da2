#pragma once
// Structural checks of each tree kind, on top of the container's own checks.
#include "formats/container_reader.h"

namespace kdpm {

struct ValidationOptions {
    bool exhaustive = false;  // the slow checks too (e.g. every triangle overlapping a leaf is listed)
};

// Throws FormatError with a one-line reason when the file is unsound. Runs ContainerReader::verify().
void validate_file(const ContainerReader& file, const ValidationOptions& options);

}  // namespace kdpm
