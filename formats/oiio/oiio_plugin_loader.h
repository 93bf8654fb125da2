#pragma once
// Finds and loads kdpm-oiio.so (oiio_plugin_api.h) on first use, once per process. Looked for:
// $KDPM_OIIO_PLUGIN (a file) when set, else lib/kdpm/ beside the executable's bin/ (the build
// tree and an installed prefix alike), else the install prefix kdpm was configured with (a
// program built against the installed package).
#include "formats/oiio/oiio_plugin_api.h"

namespace kdpm {

// The module's functions; throws std::runtime_error with a one-line reason when it cannot be
// loaded (then again at every call: nothing is cached but success).
const OiioPluginApi& oiio_plugin();

}  // namespace kdpm
