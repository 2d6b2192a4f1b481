// The only translation unit that includes the compatibility loader.
#include "glrender/tbn_lines_immediate.h"

#include "scene/errors.h"

#include <glad_compat/gl.h>

namespace twr {
namespace {

GLADapiproc callProcFunction(void* userPointer, const char* name) {
  return (*static_cast<const GlProcFunction*>(userPointer))(name);
}

}  // namespace

struct ImmediateTbnLines::Impl {
  GladGLContext gl{};
};

ImmediateTbnLines::ImmediateTbnLines(const GlProcFunction& procAddress) : impl_(std::make_unique<Impl>()) {
  GlProcFunction copy = procAddress;
  if (gladLoadGLContextUserPtr(&impl_->gl, callProcFunction, &copy) == 0) {
    throw InputError("GL: could not load the compatibility-profile entry points for immediate-mode TBN lines");
  }
  GLint profileMask = 0;
  impl_->gl.GetIntegerv(GL_CONTEXT_PROFILE_MASK, &profileMask);
  if ((profileMask & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT) == 0) {
    throw InputError(
        "GL: immediate-mode TBN lines (tbn_lines.mode = immediate) need a compatibility-profile context, "
        "but the current context is core; use mode core or create the window with a compatibility profile");
  }
}

ImmediateTbnLines::~ImmediateTbnLines() = default;

void ImmediateTbnLines::draw(const std::vector<TbnLineVertex>& lines, const mat4& clipFromView,
                             const mat4& viewFromWorld, const GlClipState& clipState,
                             const std::vector<vec4>& userClipPlanes) const {
  const GladGLContext& gl = impl_->gl;
  // The tutorial's steps. Its modelview is View * Model with model-space vertices; these
  // vertices are already in world space (see tbn_lines.h), so the modelview is View.
  gl.MatrixMode(GL_PROJECTION);
  gl.LoadMatrixf(&clipFromView[0][0]);
  gl.MatrixMode(GL_MODELVIEW);
  // Fixed function clips with glClipPlane planes, given in the coordinates the modelview
  // of the moment maps from: view space under the identity, world space under the view
  // matrix. GL_CLIP_PLANEi is the same switch as GL_CLIP_DISTANCEi.
  const auto clipPlane = [&](int slot, const vec4& plane) {
    const GLdouble equation[4] = {plane.x, plane.y, plane.z, plane.w};
    gl.ClipPlane(static_cast<GLenum>(GL_CLIP_PLANE0 + slot), equation);
  };
  gl.LoadIdentity();
  if (clipState.frustumPlaneInSlot0) clipPlane(0, clipState.frustumPlaneView);
  gl.LoadMatrixf(&viewFromWorld[0][0]);
  for (std::size_t j = 0; j < userClipPlanes.size(); ++j) {
    clipPlane(clipState.firstUserSlot + static_cast<int>(j), userClipPlanes[j]);
  }
  gl.UseProgram(0);
  gl.BindVertexArray(0);
  gl.Begin(GL_LINES);
  for (const TbnLineVertex& vertex : lines) {
    gl.Color3fv(&vertex.colour.x);
    gl.Vertex3fv(&vertex.posWorld.x);
  }
  gl.End();
}

}  // namespace twr
