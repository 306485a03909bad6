// Buffer round trips and the ownership rules shared by every wrapper.
#include <cstdint>
#include <numeric>
#include <vector>

#include <glm/glm.hpp>

#include "gl/buffer.h"
#include "gl/framebuffer.h"
#include "gl/program.h"
#include "gl/query.h"
#include "gl/renderbuffer.h"
#include "gl/shader.h"
#include "gl/texture.h"
#include "gl/vertex_array.h"
#include "tests/gpu/gl_fixture.h"

using namespace csm;

TEST_CASE("GL: buffer upload and download round trip", "[gl][buffer][quick]") {
  test::glContext();
  std::vector<glm::vec4> data(1000);
  for (std::size_t i = 0; i < data.size(); ++i)
    data[i] = glm::vec4(float(i), -float(i), 0.5f, 1e-7f);

  gl::Buffer buffer(data);
  CHECK(buffer.size() == GLsizeiptr(data.size() * sizeof(glm::vec4)));
  CHECK(buffer.download<glm::vec4>() == data);

  SECTION("a range, by element") {
    std::vector<glm::vec4> part = buffer.download<glm::vec4>(10, 500);
    REQUIRE(part.size() == 10);
    CHECK(part.front() == data[500]);
    CHECK(part.back() == data[509]);
    CHECK(buffer.download<glm::vec4>(10, 995).size() == 5);  // clipped at the end
  }
  SECTION("setSubData and read at an offset") {
    std::uint32_t word = 0xCAFEF00D;
    buffer.setSubData(16, 4, &word);
    std::uint32_t back = 0;
    buffer.read(16, 4, &back);
    CHECK(back == word);
  }
  SECTION("upload keeps the name and resizes when needed") {
    GLuint id = buffer.id();
    std::vector<std::uint32_t> small(7);
    std::iota(small.begin(), small.end(), 1u);
    buffer.upload(small);
    CHECK(buffer.id() == id);
    CHECK(buffer.size() == 28);
    CHECK(buffer.download<std::uint32_t>() == small);
  }
  SECTION("clearToZero and copyTo") {
    gl::Buffer copy(buffer.size());
    buffer.copyTo(copy, 0, 0, buffer.size());
    CHECK(copy.download<glm::vec4>() == data);
    buffer.clearToZero();
    for (const glm::vec4& v : buffer.download<glm::vec4>()) REQUIRE(v == glm::vec4(0));
  }
  SECTION("wrap takes ownership, release gives it up") {
    GLuint id = buffer.release();
    CHECK(buffer.id() == 0);
    gl::Buffer wrapped = gl::Buffer::wrap(id);
    CHECK(wrapped.id() == id);
    CHECK(wrapped.size() == GLsizeiptr(data.size() * sizeof(glm::vec4)));
  }
  CHECK(gl::checkErrors("buffer test"));
}

namespace {

// For each GL object kind: moving leaves the source empty and the object alive; only the
// last owner deletes it. The moved-from object is destroyed after a new object of the same
// kind was made, so if it still held the name, and the driver reused it, the new one dies.
template <class T, class Make, class Alive>
void checkMoveSemantics(Make make, Alive alive) {
  T a = make();
  GLuint id = a.id();
  REQUIRE(id != 0);
  REQUIRE(alive(id));

  T b = std::move(a);
  CHECK(a.id() == 0);
  CHECK(b.id() == id);
  CHECK(alive(id));

  T c{gl::NoCreate};
  c = std::move(b);
  CHECK(b.id() == 0);
  CHECK(c.id() == id);

  { T sink = std::move(c); }  // the one owner deletes it
  CHECK_FALSE(alive(id));

  T fresh = make();
  {
    T movedFrom = std::move(a);  // still empty: destroying it must not touch GL
  }
  CHECK(alive(fresh.id()));

  // Move assignment deletes what the target held.
  T target = make();
  GLuint old = target.id();
  target = make();
  CHECK_FALSE(alive(old));
  CHECK(alive(target.id()));
  CHECK(gl::checkErrors("move semantics"));
}

}  // namespace

TEST_CASE("GL: moved-from objects do not delete the GL object twice", "[gl][raii][quick]") {
  test::glContext();
  SECTION("Buffer") {
    checkMoveSemantics<gl::Buffer>([] { return gl::Buffer(64); },
                                   [](GLuint id) { return glIsBuffer(id) == GL_TRUE; });
  }
  SECTION("Texture") {
    checkMoveSemantics<gl::Texture>([] { return gl::Texture::create2D(GL_RGBA8, 4, 4); },
                                    [](GLuint id) { return glIsTexture(id) == GL_TRUE; });
  }
  SECTION("Renderbuffer") {
    checkMoveSemantics<gl::Renderbuffer>(
        [] { return gl::Renderbuffer(GL_DEPTH_COMPONENT24, 4, 4); },
        [](GLuint id) { return glIsRenderbuffer(id) == GL_TRUE; });
  }
  SECTION("Framebuffer") {
    checkMoveSemantics<gl::Framebuffer>(
        [] {
          gl::Framebuffer f;
          f.bind();  // a framebuffer name becomes an object when first bound
          gl::Framebuffer::bindDefault();
          return f;
        },
        [](GLuint id) { return glIsFramebuffer(id) == GL_TRUE; });
  }
  SECTION("VertexArray") {
    checkMoveSemantics<gl::VertexArray>(
        [] {
          gl::VertexArray v;
          v.bind();
          gl::VertexArray::unbind();
          return v;
        },
        [](GLuint id) { return glIsVertexArray(id) == GL_TRUE; });
  }
  SECTION("Query") {
    checkMoveSemantics<gl::Query>(
        [] {
          gl::Query q;
          q.begin();
          q.end();
          return q;
        },
        [](GLuint id) { return glIsQuery(id) == GL_TRUE; });
  }
  SECTION("Shader") {
    checkMoveSemantics<gl::Shader>([] { return gl::Shader(GL_COMPUTE_SHADER, "move test"); },
                                   [](GLuint id) { return glIsShader(id) == GL_TRUE; });
  }
  SECTION("Program") {
    checkMoveSemantics<gl::Program>([] { return gl::Program("move test"); },
                                    [](GLuint id) { return glIsProgram(id) == GL_TRUE; });
  }
}
