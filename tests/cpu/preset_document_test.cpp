// The preset as a document (app/preset_document.h), without a window.
#include <filesystem>
#include <string>
#include <unistd.h>

#include <catch2/catch.hpp>

#include "app/preset.h"
#include "app/preset_document.h"

namespace csm {

TEST_CASE("PresetDocument: edits, what differs from the file, the title, and save as",
          "[preset][quick]") {
  PresetDocument doc;
  Preset p = defaultPreset();
  doc.opened(p, "");
  CHECK_FALSE(doc.modified());
  CHECK(doc.title() == "csmhair - " + p.name);

  // A camera move is not a modification; a parameter is.
  Preset next = doc.current();
  next.view.camera.yaw += 10.0f;
  doc.applied(next);
  CHECK_FALSE(doc.modified());
  next.scene.wind.strength += 1.0f;
  doc.applied(next);
  REQUIRE(doc.modifiedKeys().size() == 1);
  CHECK(doc.modifiedKeys()[0] == "wind.strength");
  CHECK(doc.title() == "csmhair - " + p.name + " *");
  CHECK(doc.edited().scene.wind.strength == next.scene.wind.strength);

  // An edit refused: the widgets show what runs again.
  doc.edited().scene.wind.strength = 99.0f;
  doc.discardEdits();
  CHECK(doc.edited().scene.wind.strength == next.scene.wind.strength);

  // Saved: the file is the document's, nothing differs from it, and it reads back as it runs.
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("csm_document_" + std::to_string(::getpid()) + ".json");
  std::string error;
  REQUIRE(doc.saveAs(path.string(), &error));
  CHECK(doc.path() == path.string());
  CHECK_FALSE(doc.modified());
  CHECK(doc.title() == "csmhair - " + p.name + " (" + path.string() + ")");
  Preset read = defaultPreset();
  PresetErrors errors;
  REQUIRE(loadPreset(path.string(), read, errors));
  CHECK(read.scene.wind.strength == next.scene.wind.strength);
  std::filesystem::remove(path);

  // A folder that is not there: refused with the path, the document as it was.
  CHECK_FALSE(doc.saveAs("/nonexistent/folder/x.json", &error));
  CHECK_THAT(error, Catch::Contains("/nonexistent/folder/x.json"));
  CHECK(doc.path() == path.string());
}

}  // namespace csm
