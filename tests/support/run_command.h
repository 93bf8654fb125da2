#pragma once
// Runs a kdpm executable in a shell, capturing its output, for end-to-end tests.
#include <string>

namespace kdpm::test {

struct CommandResult {
    int exit_code;
    std::string output;  // stdout and stderr together
};

// Runs `command` in /bin/sh with no input, stdout and stderr captured together.
CommandResult run_shell(const std::string& command);

// `command` starts with a tool name (e.g. "kdpm-validate x.kdg"); it is run from build/bin.
CommandResult run_tool(const std::string& command);

std::string tool_path(const std::string& tool);
std::string source_path(const std::string& relative);

// Folder of the real test scenes (../shared/scenes or $KDPM_SCENES); empty when absent.
std::string shared_scenes_dir();

}  // namespace kdpm::test
