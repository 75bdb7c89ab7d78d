// Depth read and image compositing. See AMRDualMeshCompositor.h.
#include "AMRDualMeshCompositor.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
// OpenGL entry points: VTK::glew up to VTK 9.3, VTK::glad from 9.4 (both optional dependencies
// in vtk.module; the module system defines VTK_MODULE_ENABLE_VTK_glad to 0 or 1).
#if VTK_MODULE_ENABLE_VTK_glad
#include "vtk_glad.h"
#else
#include "vtk_glew.h"
#endif

#include <algorithm>

namespace amrdm_vtk
{
namespace
{
const char* kFragmentShader = R"(//VTK::System::Dec
in vec2 texCoord;
uniform sampler2D img;
//VTK::Output::Dec
void main()
{
  gl_FragData[0] = texture(img, texCoord);
}
)";
// Window depth from a one-channel texture; pixels at 1 (no surface) write nothing.
const char* kDepthShader = R"(//VTK::System::Dec
in vec2 texCoord;
uniform sampler2D depthImg;
//VTK::Output::Dec
void main()
{
  float d = texture(depthImg, texCoord).r;
  if (d >= 1.0)
  {
    discard;
  }
  gl_FragDepth = d;
  gl_FragData[0] = vec4(0.0);
}
)";
// (Re)allocates `tex` as a float texture of `components` channels when the size changed, and
// uploads `data`; then binds `quad`'s program (compiled on first use). False when it did not
// compile.
bool UploadAndReady(vtkOpenGLRenderWindow* renWin,
  vtkSmartPointer<vtkTextureObject>& tex,
  int size[2],
  std::unique_ptr<vtkOpenGLQuadHelper>& quad,
  const char* shader,
  int width,
  int height,
  int components,
  const float* data)
{
  if (!tex)
  {
    tex = vtkSmartPointer<vtkTextureObject>::New();
  }
  tex->SetContext(renWin);
  const GLenum format = components == 1 ? GL_RED : GL_RGBA;
  if (size[0] != width || size[1] != height || !tex->GetHandle())
  {
    tex->SetInternalFormat(components == 1 ? GL_R32F : GL_RGBA32F);
    tex->SetFormat(format);
    tex->SetDataType(GL_FLOAT);
    tex->SetMinificationFilter(vtkTextureObject::Nearest);
    tex->SetMagnificationFilter(vtkTextureObject::Nearest);
    tex->Allocate2D(width, height, components, VTK_FLOAT);
    size[0] = width;
    size[1] = height;
  }
  tex->Bind();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, format, GL_FLOAT, data);
  if (!quad)
  {
    quad.reset(new vtkOpenGLQuadHelper(renWin, nullptr, shader, ""));
  }
  else
  {
    renWin->GetShaderCache()->ReadyShaderProgram(quad->Program);
  }
  return quad->Program && quad->Program->GetCompiled();
}
}

Compositor::Compositor() = default;
Compositor::~Compositor() = default;

bool Compositor::ReadDepth(vtkRenderer* ren,
  int x0,
  int y0,
  int width,
  int height,
  std::vector<float>& depth)
{
  depth.assign(static_cast<std::size_t>(width) * height, 1.0f);
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!renWin)
  {
    return false;
  }
  vtkOpenGLState* ostate = renWin->GetState();
  GLint drawFramebuffer = 0, samples = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer);
  glGetIntegerv(GL_SAMPLES, &samples);
  ostate->PushFramebufferBindings();
  ostate->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, drawFramebuffer);
  if (samples > 0)
  {
    if (!this->DepthFBO)
    {
      this->DepthFBO = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
      this->DepthFBO->SetContext(renWin);
    }
    if (this->FBOSize[0] != width || this->FBOSize[1] != height)
    {
      // Depth formats must match for a depth blit: 32 bits as the render framebuffer.
      this->DepthFBO->ReleaseGraphicsResources(renWin);
      this->DepthFBO->SetContext(renWin);
      ostate->PushFramebufferBindings();
      this->DepthFBO->PopulateFramebuffer(
        width, height, true, 1, VTK_UNSIGNED_CHAR, true, 32, 0, renWin->GetStencilCapable() != 0);
      ostate->PopFramebufferBindings();
      this->FBOSize[0] = width;
      this->FBOSize[1] = height;
    }
    ostate->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, drawFramebuffer);
    this->DepthFBO->Bind(GL_DRAW_FRAMEBUFFER);
    vtkOpenGLState::ScopedglEnableDisable scissor(ostate, GL_SCISSOR_TEST);
    ostate->vtkglDisable(GL_SCISSOR_TEST);
    glBlitFramebuffer(
      x0, y0, x0 + width, y0 + height, 0, 0, width, height, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    this->DepthFBO->Bind(GL_READ_FRAMEBUFFER);
    glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  }
  else
  {
    glReadPixels(x0, y0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  }
  ostate->PopFramebufferBindings();
  return glGetError() == GL_NO_ERROR;
}

void Compositor::Draw(vtkRenderer* ren, int width, int height, const float* rgba)
{
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!renWin || width <= 0 || height <= 0)
  {
    return;
  }
  vtkOpenGLState* ostate = renWin->GetState();
  if (!UploadAndReady(renWin,
        this->Texture,
        this->TextureSize,
        this->Quad,
        kFragmentShader,
        width,
        height,
        4,
        rgba))
  {
    return;
  }
  vtkOpenGLState::ScopedglEnableDisable blend(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthTest(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(ostate);
  vtkOpenGLState::ScopedglDepthMask depthMask(ostate);
  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglDepthMask(GL_FALSE);
  this->Texture->Activate();
  this->Quad->Program->SetUniformi("img", this->Texture->GetTextureUnit());
  this->Quad->Render();
  this->Texture->Deactivate();
}

void Compositor::DrawDepth(vtkRenderer* ren, int width, int height, const float* depth)
{
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!renWin || width <= 0 || height <= 0 || !depth)
  {
    return;
  }
  vtkOpenGLState* ostate = renWin->GetState();
  if (!UploadAndReady(renWin,
        this->DepthTexture,
        this->DepthTextureSize,
        this->DepthQuad,
        kDepthShader,
        width,
        height,
        1,
        depth))
  {
    return;
  }
  GLint depthFunc = GL_LESS;
  glGetIntegerv(GL_DEPTH_FUNC, &depthFunc);
  vtkOpenGLState::ScopedglEnableDisable blend(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthTest(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglDepthMask depthMask(ostate);
  vtkOpenGLState::ScopedglColorMask colorMask(ostate);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  this->DepthTexture->Activate();
  this->DepthQuad->Program->SetUniformi("depthImg", this->DepthTexture->GetTextureUnit());
  this->DepthQuad->Render();
  this->DepthTexture->Deactivate();
  ostate->vtkglDepthFunc(static_cast<unsigned int>(depthFunc));
}

void Compositor::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->DepthTexture)
  {
    this->DepthTexture->ReleaseGraphicsResources(window);
  }
  if (this->DepthQuad)
  {
    this->DepthQuad->ReleaseGraphicsResources(window);
    this->DepthQuad.reset();
  }
  this->DepthTextureSize[0] = this->DepthTextureSize[1] = 0;
  if (this->Texture)
  {
    this->Texture->ReleaseGraphicsResources(window);
  }
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(window);
    this->Quad.reset();
  }
  if (this->DepthFBO)
  {
    this->DepthFBO->ReleaseGraphicsResources(window);
  }
  this->TextureSize[0] = this->TextureSize[1] = 0;
  this->FBOSize[0] = this->FBOSize[1] = 0;
}
}
