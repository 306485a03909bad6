// Where the viewer finds presets: the folder of the preset it opened, ./presets, presets/
// beside the executable and up to two folders above it (a build tree inside the source
// tree), and the source tree it was built from.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace csm {

// Existing folders, each once (by canonical path), most specific first.
std::vector<std::filesystem::path> presetDirectories(const std::string& openedPreset);
// The *.json files of those folders, sorted by folder then name.
std::vector<std::filesystem::path> listPresets(const std::vector<std::filesystem::path>& dirs);
// Where "Save as" puts a bare file name: the opened preset's folder, else the first preset
// folder, else the current directory. Adds ".json" when there is no extension.
std::filesystem::path saveAsPath(const std::string& name, const std::string& openedPreset,
                                 const std::vector<std::filesystem::path>& dirs);

}  // namespace csm
