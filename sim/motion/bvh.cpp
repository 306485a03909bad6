#include "sim/motion/bvh.h"

#include <charconv>
#include <cmath>
#include <cstddef>
#include <optional>

#include "sim/base/file_io.h"

namespace csm {
namespace {

// A clip of a few hours at 120 fps and a hundred joints stays far below this.
constexpr uint64_t kMaxBvhBytes = uint64_t(1) << 30;

// The text as lines of whitespace-separated words, read a word at a time with the line it is on.
class Words {
 public:
  Words(std::string_view text, std::string_view name) : name_(name) {
    size_t start = 0;
    while (start <= text.size()) {
      size_t end = text.find('\n', start);
      if (end == std::string_view::npos) end = text.size();
      std::string_view line = text.substr(start, end - start);
      lines_.push_back(line);
      start = end + 1;
    }
  }

  // The next word, or nullopt at the end of the text.
  std::optional<std::string_view> next() {
    while (line_ < lines_.size()) {
      std::string_view l = lines_[line_];
      while (pos_ < l.size() && isSpace(l[pos_])) ++pos_;
      if (pos_ < l.size()) {
        const size_t start = pos_;
        while (pos_ < l.size() && !isSpace(l[pos_])) ++pos_;
        wordLine_ = line_;
        return l.substr(start, pos_ - start);
      }
      ++line_;
      pos_ = 0;
    }
    return std::nullopt;  // a message names the line of the last word read
  }
  // The rest of the current line, trimmed (a joint's name).
  std::string_view restOfLine() {
    if (line_ >= lines_.size()) return {};
    std::string_view l = lines_[line_].substr(pos_);
    pos_ = lines_[line_].size();
    while (!l.empty() && isSpace(l.front())) l.remove_prefix(1);
    while (!l.empty() && isSpace(l.back())) l.remove_suffix(1);
    return l;
  }
  // "name:LINE: message", LINE of the word read last.
  bool fail(std::string* error, const std::string& message) const {
    if (error) *error = std::string(name_) + ":" + std::to_string(wordLine_ + 1) + ": " + message;
    return false;
  }

 private:
  static bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
  }
  std::string_view name_;
  std::vector<std::string_view> lines_;
  size_t line_ = 0, pos_ = 0, wordLine_ = 0;
};

bool equalsNoCase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) !=
        std::tolower(static_cast<unsigned char>(b[i])))
      return false;
  return true;
}

std::optional<double> number(std::string_view w) {
  if (!w.empty() && w.front() == '+') w.remove_prefix(1);
  double v = 0.0;
  const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
  if (ec != std::errc() || end != w.data() + w.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::optional<BvhChannel> channelNamed(std::string_view w) {
  static constexpr std::string_view kNames[] = {"Xposition", "Yposition", "Zposition",
                                                "Xrotation", "Yrotation", "Zrotation"};
  for (int i = 0; i < 6; ++i)
    if (equalsNoCase(w, kNames[i])) return BvhChannel(i);
  return std::nullopt;
}

class Parser {
 public:
  Parser(std::string_view text, std::string_view name, BvhClip& out, std::string* error)
      : words_(text, name), out_(out), error_(error) {}

  bool run() {
    auto w = words_.next();
    if (!w || !equalsNoCase(*w, "HIERARCHY"))
      return fail("expected HIERARCHY at the start: this is not a BVH file");
    w = words_.next();
    while (w && (equalsNoCase(*w, "ROOT"))) {
      if (!joint(-1)) return false;
      w = words_.next();
    }
    if (out_.joints.empty()) return fail("expected ROOT after HIERARCHY");
    if (!w) return fail("the file ends before MOTION");
    if (!equalsNoCase(*w, "MOTION"))
      return fail("expected MOTION or ROOT, found '" + std::string(*w) + "'");
    return motion();
  }

 private:
  bool fail(const std::string& message) { return words_.fail(error_, message); }

  bool expect(std::string_view word) {
    auto w = words_.next();
    if (!w) return fail("the file ends where '" + std::string(word) + "' was expected");
    if (!equalsNoCase(*w, word))
      return fail("expected '" + std::string(word) + "', found '" + std::string(*w) + "'");
    return true;
  }

  bool vec3(glm::dvec3& v, std::string_view what) {
    for (int i = 0; i < 3; ++i) {
      auto w = words_.next();
      if (!w) return fail("the file ends inside " + std::string(what));
      auto x = number(*w);
      if (!x) return fail(std::string(what) + ": '" + std::string(*w) + "' is not a finite number");
      v[i] = *x;
    }
    return true;
  }

  // After ROOT or JOINT: the name, then the braces.
  bool joint(int parent) {
    if (depth_ > 256) return fail("joints nested more than 256 deep");
    BvhJoint j;
    j.name = std::string(words_.restOfLine());
    if (j.name.empty()) return fail("a joint without a name");
    j.parent = parent;
    if (!expect("{")) return false;
    if (!expect("OFFSET")) return false;
    if (!vec3(j.offset, "OFFSET")) return false;
    const int index = int(out_.joints.size());
    auto w = words_.next();
    if (w && equalsNoCase(*w, "CHANNELS")) {
      auto n = words_.next();
      std::optional<double> count = n ? number(*n) : std::nullopt;
      if (!count || *count < 0 || *count > 6 || *count != std::floor(*count))
        return fail("CHANNELS: expected a count from 0 to 6, found '" + std::string(n ? *n : "") +
                    "'");
      for (int c = 0; c < int(*count); ++c) {
        auto cw = words_.next();
        if (!cw) return fail("the file ends inside CHANNELS");
        auto ch = channelNamed(*cw);
        if (!ch)
          return fail("'" + std::string(*cw) +
                      "' is not a channel (Xposition, Yposition, Zposition, Xrotation, "
                      "Yrotation or Zrotation)");
        for (BvhChannel seen : j.channels)
          if (seen == *ch)
            return fail("channel '" + std::string(*cw) + "' twice on joint '" + j.name + "'");
        j.channels.push_back(*ch);
      }
      w = words_.next();
    }
    j.firstChannel = out_.channelCount;
    out_.channelCount += int(j.channels.size());
    out_.joints.push_back(std::move(j));
    ++depth_;
    while (true) {
      if (!w) return fail("the file ends inside joint '" + out_.joints[index].name + "'");
      if (*w == "}") break;
      if (equalsNoCase(*w, "JOINT")) {
        if (!joint(index)) return false;
      } else if (equalsNoCase(*w, "End")) {
        if (!expect("Site") || !expect("{") || !expect("OFFSET")) return false;
        glm::dvec3 end;
        if (!vec3(end, "the end site's OFFSET") || !expect("}")) return false;
        out_.joints[index].endSite = end;
        out_.joints[index].hasEndSite = true;
      } else {
        return fail("expected JOINT, End Site or '}' in joint '" + out_.joints[index].name +
                    "', found '" + std::string(*w) + "'");
      }
      w = words_.next();
    }
    --depth_;
    return true;
  }

  bool motion() {
    if (!expect("Frames:")) return false;
    auto n = words_.next();
    std::optional<double> frames = n ? number(*n) : std::nullopt;
    if (!frames || *frames < 1 || *frames != std::floor(*frames) || *frames > 1e8)
      return fail("Frames: expected a count of one or more, found '" + std::string(n ? *n : "") +
                  "'");
    if (!expect("Frame") || !expect("Time:")) return false;
    auto t = words_.next();
    std::optional<double> dt = t ? number(*t) : std::nullopt;
    if (!dt || !(*dt > 0.0) || *dt > 10.0)
      return fail("Frame Time: expected seconds a frame (above 0, at most 10), found '" +
                  std::string(t ? *t : "") + "'");
    out_.frameTime = *dt;
    const size_t count = size_t(*frames) * size_t(out_.channelCount);
    if (count > kMaxBvhBytes / 2) return fail("Frames: too many values for a clip");
    out_.values.reserve(count);
    for (size_t i = 0; i < count; ++i) {
      auto w = words_.next();
      if (!w) {
        const size_t frame = i / out_.channelCount;
        return fail("the file ends in frame " + std::to_string(frame + 1) + " of " +
                    std::to_string(size_t(*frames)) + " (" + std::to_string(i % out_.channelCount) +
                    " of its " + std::to_string(out_.channelCount) + " values)");
      }
      auto v = number(*w);
      if (!v)
        return fail("frame " + std::to_string(i / out_.channelCount + 1) + ", value " +
                    std::to_string(i % out_.channelCount + 1) + ": '" + std::string(*w) +
                    "' is not a finite number");
      out_.values.push_back(*v);
    }
    if (auto w = words_.next())
      return fail("more values than Frames: " + std::to_string(size_t(*frames)) + " frames of " +
                  std::to_string(out_.channelCount) + " channels");
    if (out_.channelCount == 0) return fail("no joint has a channel: nothing moves");
    return true;
  }

  Words words_;
  BvhClip& out_;
  std::string* error_;
  int depth_ = 0;
};

glm::dquat axisRotation(BvhChannel c, double degrees) {
  static const glm::dvec3 kAxes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  return glm::angleAxis(glm::radians(degrees), kAxes[int(c) - int(BvhChannel::Xrotation)]);
}

}  // namespace

bool parseBvh(std::string_view text, std::string_view name, BvhClip& out, std::string* error) {
  out = {};
  Parser parser(text, name, out, error);
  if (parser.run()) return true;
  out = {};
  return false;
}

bool readBvh(const std::string& path, BvhClip& out, std::string* error) {
  auto bytes = io::detail::readFileBytes(path, kMaxBvhBytes, error);
  if (!bytes) return false;
  const std::string_view text(reinterpret_cast<const char*>(bytes->data()), bytes->size());
  return parseBvh(text, path, out, error);
}

void jointPoses(const BvhClip& clip, int frame, std::vector<JointPose>& out) {
  out.resize(clip.joints.size());
  const double* v = clip.values.data() + size_t(frame) * size_t(clip.channelCount);
  for (size_t i = 0; i < clip.joints.size(); ++i) {
    const BvhJoint& j = clip.joints[i];
    glm::dvec3 place = j.offset;
    glm::dquat turn(1.0, 0.0, 0.0, 0.0);
    for (size_t c = 0; c < j.channels.size(); ++c) {
      const double x = v[j.firstChannel + int(c)];
      const BvhChannel ch = j.channels[c];
      if (ch <= BvhChannel::Zposition) {
        place[int(ch)] = x;
      } else {
        turn = turn * axisRotation(ch, x);
      }
    }
    JointPose& p = out[i];
    if (j.parent < 0) {
      p.rotation = turn;
      p.position = place;
    } else {
      const JointPose& parent = out[size_t(j.parent)];
      p.rotation = glm::normalize(parent.rotation * turn);
      p.position = parent.rotation * place + parent.position;
    }
  }
}

}  // namespace csm
