#include "app/viewer_presets.h"

#include <algorithm>
#include <system_error>

namespace csm {
namespace fs = std::filesystem;
namespace {

fs::path executableDir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe.parent_path();
}

}  // namespace

std::vector<fs::path> presetDirectories(const std::string& openedPreset) {
  std::vector<fs::path> candidates;
  if (!openedPreset.empty()) candidates.push_back(fs::absolute(openedPreset).parent_path());
  candidates.push_back(fs::current_path() / "presets");
  const fs::path exe = executableDir();
  if (!exe.empty())
    for (const fs::path& up : {exe, exe.parent_path(), exe.parent_path().parent_path()})
      candidates.push_back(up / "presets");
#ifdef CSM_SOURCE_DIR
  candidates.push_back(fs::path(CSM_SOURCE_DIR) / "presets");
#endif
  std::vector<fs::path> dirs;
  for (const fs::path& c : candidates) {
    std::error_code ec;
    if (!fs::is_directory(c, ec)) continue;
    const fs::path canonical = fs::weakly_canonical(c, ec);
    if (ec) continue;
    if (std::find(dirs.begin(), dirs.end(), canonical) == dirs.end()) dirs.push_back(canonical);
  }
  return dirs;
}

std::vector<fs::path> listPresets(const std::vector<fs::path>& dirs) {
  std::vector<fs::path> out;
  for (const fs::path& dir : dirs) {
    std::vector<fs::path> here;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
      std::error_code fec;
      if (it->path().extension() == ".json" && it->is_regular_file(fec)) here.push_back(it->path());
    }
    std::sort(here.begin(), here.end());
    for (const fs::path& p : here)
      if (std::find(out.begin(), out.end(), p) == out.end()) out.push_back(p);
  }
  return out;
}

fs::path saveAsPath(const std::string& name, const std::string& openedPreset,
                    const std::vector<fs::path>& dirs) {
  fs::path p(name);
  if (p.extension().empty()) p += ".json";
  if (p.has_parent_path() || p.is_absolute()) return p;
  if (!openedPreset.empty()) return fs::absolute(openedPreset).parent_path() / p;
  if (!dirs.empty()) return dirs.front() / p;
  return fs::current_path() / p;
}

}  // namespace csm
