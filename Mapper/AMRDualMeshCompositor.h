// The OpenGL side of vtkAMRDualMeshVolumeMapper: reads the depth of what the renderer already
// drew (resolving a multisampled framebuffer through a blit) and draws the renderer's float
// premultiplied RGBA image over it as a full-viewport quad. Private to the mapper; not wrapped.
#ifndef AMRDualMeshCompositor_h
#define AMRDualMeshCompositor_h

#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <memory>
#include <vector>

class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkRenderer;
class vtkTextureObject;
class vtkWindow;

namespace amrdm_vtk
{
class Compositor
{
public:
  Compositor();
  ~Compositor();

  /// Reads the depth of the renderer's tiled viewport (`width` x `height` at `x0`, `y0` in the
  /// window) from the framebuffer being drawn into; rows from the bottom. A multisampled
  /// framebuffer is resolved into a single-sample one first (glReadPixels of depth fails on
  /// multisampled buffers). Returns false (depth cleared to 1) when there is no OpenGL window.
  bool ReadDepth(vtkRenderer* ren,
    int x0,
    int y0,
    int width,
    int height,
    std::vector<float>& depth);

  /// Uploads `rgba` (width*height premultiplied float RGBA, rows from the bottom) and blends it
  /// over the current viewport with (GL_ONE, GL_ONE_MINUS_SRC_ALPHA), depth test and depth writes
  /// off; all OpenGL state is restored.
  void Draw(vtkRenderer* ren, int width, int height, const float* rgba);

  /// Writes `depth` (width*height window depths in [0, 1], rows from the bottom; 1 = nothing)
  /// into the current viewport's depth buffer where it is below 1: a full-viewport quad with
  /// colour writes off, depth test GL_ALWAYS and depth writes on (the surfaces it comes from
  /// already stop at the opaque depth read by ReadDepth); all OpenGL state is restored.
  void DrawDepth(vtkRenderer* ren, int width, int height, const float* depth);

  /// Releases the textures, the quads and the framebuffer.
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  Compositor(const Compositor&) = delete;
  Compositor& operator=(const Compositor&) = delete;

  vtkSmartPointer<vtkTextureObject> Texture;
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  vtkSmartPointer<vtkTextureObject> DepthTexture;
  std::unique_ptr<vtkOpenGLQuadHelper> DepthQuad;
  int DepthTextureSize[2] = { 0, 0 };
  vtkSmartPointer<vtkOpenGLFramebufferObject> DepthFBO;
  int TextureSize[2] = { 0, 0 };
  int FBOSize[2] = { 0, 0 };
};
}

#endif
