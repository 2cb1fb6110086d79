// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

// lattice-mesh --png, drawn by VTK 9 without a display. Debian's VTK 9.1 is built for X only (no
// OSMesa, no EGL window), so the OpenGL context is made here through EGL, on Mesa's surfaceless
// platform (llvmpipe, no GPU and no X server needed) or an EGL device, and handed to a
// vtkGenericOpenGLRenderWindow, which draws into whatever context is current.

#include "render_png.h"

#include <stdexcept>

#ifndef LATTICE_MESHER_3_WITH_VTK

namespace render_png {

void check_available()
{
  throw std::runtime_error("--png: lattice-mesh was built without VTK; install libvtk9-dev and rebuild");
}

void write_png(const std::string&, const std::vector<std::array<double, 3> >&, const std::vector<std::array<int, 4> >&,
               const std::vector<double>&, const Picture_options&)
{
  check_available();
}

} // namespace render_png

#else // LATTICE_MESHER_3_WITH_VTK

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkColorTransferFunction.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkDoubleArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPoints.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnstructuredGrid.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

// VTK 9.1 initializes GLEW through glewInit(), which Debian's GLEW builds for GLX: after loading
// every OpenGL function it calls glxewInit(), which fails without a GLX display, and VTK then
// refuses the context. The OpenGL functions GLEW loaded are libglvnd's dispatch stubs, which serve
// an EGL context as well; only the GLX extensions are missing, and VTK does not use them with a
// context it did not make. So while an EGL context is current, glxewInit() succeeds; otherwise
// GLEW's own runs. (The program exports this symbol: see CMakeLists.txt.)
extern "C" unsigned int glxewInit()
{
  if(eglGetCurrentContext() != EGL_NO_CONTEXT) return 0;   // GLEW_OK
  typedef unsigned int (*Init)();
  static const Init next = reinterpret_cast<Init>(dlsym(RTLD_NEXT, "glxewInit"));
  return next != nullptr ? next() : 1;   // GLEW_ERROR_NO_GL_VERSION
}

namespace render_png {

void check_available() {}

namespace {

// An OpenGL 3.2 core context current on this thread, with a pbuffer of the picture's size.
class Egl_context
{
public:
  Egl_context(int width, int height)
  {
    std::string tried;
    for(EGLDisplay display : candidate_displays()) {
      if(make_current(display, width, height)) return;
      tried += (tried.empty() ? "" : ", ") + error_name(eglGetError());
      eglTerminate(display);
    }
    throw std::runtime_error("--png: no OpenGL context to draw with: EGL found no display that gives one" +
                             (tried.empty() ? std::string() : " (" + tried + ")") +
                             "; Mesa's EGL (libegl-mesa0) draws without a GPU or an X server");
  }
  ~Egl_context()
  {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglDestroySurface(display_, surface_);
    eglTerminate(display_);
  }
  Egl_context(const Egl_context&) = delete;
  Egl_context& operator=(const Egl_context&) = delete;

private:
  static bool has_extension(const char* extensions, const char* name)
  {
    if(extensions == nullptr) return false;
    const std::size_t n = std::strlen(name);
    for(const char* p = std::strstr(extensions, name); p != nullptr; p = std::strstr(p + n, name))
      if((p == extensions || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
  }

  static std::string error_name(EGLint e)
  {
    char buffer[32];
    std::snprintf(buffer, sizeof(buffer), "EGL error 0x%04x", unsigned(e));
    return buffer;
  }

  // Mesa's surfaceless platform first (software or a render node), then each EGL device (e.g.
  // NVIDIA's), then the default display.
  static std::vector<EGLDisplay> candidate_displays()
  {
    std::vector<EGLDisplay> displays;
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if(has_extension(client, "EGL_MESA_platform_surfaceless")) {
      EGLDisplay d = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
      if(d != EGL_NO_DISPLAY) displays.push_back(d);
    }
    if(has_extension(client, "EGL_EXT_platform_device")) {
      const auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
      EGLDeviceEXT devices[16];
      EGLint n = 0;
      if(query_devices != nullptr && query_devices(16, devices, &n))
        for(EGLint i = 0; i < n; ++i) {
          EGLDisplay d = eglGetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
          if(d != EGL_NO_DISPLAY) displays.push_back(d);
        }
    }
    EGLDisplay d = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if(d != EGL_NO_DISPLAY) displays.push_back(d);
    return displays;
  }

  bool make_current(EGLDisplay display, int width, int height)
  {
    EGLint major = 0, minor = 0;
    if(!eglInitialize(display, &major, &minor) || !eglBindAPI(EGL_OPENGL_API)) return false;
    const EGLint config_attributes[] = { EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                         EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
                                         EGL_DEPTH_SIZE, 24, EGL_NONE };
    EGLConfig config;
    EGLint configs = 0;
    if(!eglChooseConfig(display, config_attributes, &config, 1, &configs) || configs < 1) return false;
    const EGLint surface_attributes[] = { EGL_WIDTH, width, EGL_HEIGHT, height, EGL_NONE };
    const EGLSurface surface = eglCreatePbufferSurface(display, config, surface_attributes);
    if(surface == EGL_NO_SURFACE) return false;
    const EGLint context_attributes[] = { EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 2,
                                          EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                          EGL_NONE };
    const EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attributes);
    if(context == EGL_NO_CONTEXT) { eglDestroySurface(display, surface); return false; }
    if(!eglMakeCurrent(display, surface, surface, context)) {
      eglDestroyContext(display, context);
      eglDestroySurface(display, surface);
      return false;
    }
    display_ = display;
    surface_ = surface;
    context_ = context;
    return true;
  }

  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLSurface surface_ = EGL_NO_SURFACE;
  EGLContext context_ = EGL_NO_CONTEXT;
};

// viridis (matplotlib's), from the smallest value to the largest
void viridis(vtkLookupTable* table, double low, double high)
{
  static const double stops[9][3] = {
    { 0.267004, 0.004874, 0.329415 }, { 0.282623, 0.140926, 0.457517 }, { 0.229739, 0.322361, 0.545706 },
    { 0.172719, 0.448791, 0.557885 }, { 0.127568, 0.566949, 0.550556 }, { 0.134692, 0.658636, 0.517649 },
    { 0.369214, 0.788888, 0.382914 }, { 0.678489, 0.863742, 0.189503 }, { 0.993248, 0.906157, 0.143936 } };
  vtkNew<vtkColorTransferFunction> f;
  for(int i = 0; i < 9; ++i) f->AddRGBPoint(i / 8., stops[i][0], stops[i][1], stops[i][2]);
  const int n = 256;
  table->SetNumberOfTableValues(n);
  for(int i = 0; i < n; ++i) {
    double rgb[3];
    f->GetColor(double(i) / (n - 1), rgb);
    table->SetTableValue(i, rgb[0], rgb[1], rgb[2], 1.);
  }
  table->SetTableRange(low, high);
}

// the faces of `grid` in exactly one of its tetrahedra, with the cell data of that tetrahedron
vtkNew<vtkDataSetSurfaceFilter> boundary(vtkUnstructuredGrid* grid)
{
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputData(grid);
  surface->Update();
  return surface;
}

vtkNew<vtkTextActor> caption(const std::string& text, int font_size)
{
  vtkNew<vtkTextActor> actor;
  actor->SetInput(text.c_str());
  actor->GetTextProperty()->SetFontSize(font_size);
  actor->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
  actor->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  actor->GetPositionCoordinate()->SetValue(0.03, 0.94);
  actor->GetTextProperty()->SetVerticalJustificationToTop();
  return actor;
}

} // namespace

void write_png(const std::string& file, const std::vector<std::array<double, 3> >& points,
               const std::vector<std::array<int, 4> >& tets, const std::vector<double>& theta_min,
               const Picture_options& options)
{
  if(theta_min.size() != tets.size())
    throw std::invalid_argument("--png: " + std::to_string(theta_min.size()) + " theta_min values for " +
                                std::to_string(tets.size()) + " tetrahedra");
  for(const std::array<int, 4>& t : tets)
    for(int v : t)
      if(v < 0 || std::size_t(v) >= points.size())
        throw std::invalid_argument("--png: vertex index " + std::to_string(v) + " out of range");
  if(options.width < 2 || options.height < 1)
    throw std::invalid_argument("--png: the picture needs a positive size");

  // the bounding box, its centre the clipping plane's point and the camera's focal point
  double bounds[6] = { 0., 1., 0., 1., 0., 1. };
  if(!points.empty())
    for(std::size_t i = 0; i < 3; ++i) {
      const auto [lo, hi] = std::minmax_element(points.begin(), points.end(),
        [i](const std::array<double, 3>& a, const std::array<double, 3>& b) { return a[i] < b[i]; });
      bounds[2 * i] = (*lo)[i];
      bounds[2 * i + 1] = (*hi)[i];
    }
  // the plane z = centre[2] faces the camera, which looks from +z (and from +x, above)
  const double centre[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5]) };

  vtkNew<vtkPoints> vtk_points;
  vtk_points->SetDataTypeToDouble();
  vtk_points->SetNumberOfPoints(vtkIdType(points.size()));
  for(std::size_t v = 0; v < points.size(); ++v) vtk_points->SetPoint(vtkIdType(v), points[v].data());

  // all the tetrahedra, and those whose centroid lies below the plane z = centre[2]
  vtkNew<vtkCellArray> all_cells, kept_cells;
  vtkNew<vtkDoubleArray> kept_theta;
  kept_theta->SetName("theta_min");
  std::size_t bad = 0;
  for(std::size_t t = 0; t < tets.size(); ++t) {
    const vtkIdType ids[4] = { tets[t][0], tets[t][1], tets[t][2], tets[t][3] };
    all_cells->InsertNextCell(4, ids);
    if(theta_min[t] < options.bad_angle) ++bad;
    double z = 0.;
    for(int v : tets[t]) z += points[std::size_t(v)][2];
    if(z / 4. < centre[2]) {
      kept_cells->InsertNextCell(4, ids);
      kept_theta->InsertNextValue(theta_min[t]);
    }
  }
  vtkNew<vtkUnstructuredGrid> all, kept;
  all->SetPoints(vtk_points);
  all->SetCells(VTK_TETRA, all_cells);
  kept->SetPoints(vtk_points);
  kept->SetCells(VTK_TETRA, kept_cells);
  kept->GetCellData()->SetScalars(kept_theta);

  const Egl_context context(options.width, options.height);

  // left: the boundary, flat shaded, its edges drawn
  vtkNew<vtkDataSetSurfaceFilter> all_surface = boundary(all);
  vtkNew<vtkPolyDataMapper> surface_mapper;
  surface_mapper->SetInputConnection(all_surface->GetOutputPort());
  surface_mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> surface_actor;
  surface_actor->SetMapper(surface_mapper);
  vtkProperty* p = surface_actor->GetProperty();
  p->SetInterpolationToFlat();
  p->SetColor(0.80, 0.84, 0.90);
  p->EdgeVisibilityOn();
  p->SetEdgeColor(0.15, 0.15, 0.2);
  p->SetAmbient(0.25);
  p->SetDiffuse(0.75);

  // right: the kept tetrahedra by theta_min, red below the bad angle
  vtkNew<vtkLookupTable> table;
  viridis(table, options.bad_angle, std::acos(1. / 3.) * 180. / std::acos(-1.));   // up to a regular tetrahedron's
  table->SetBelowRangeColor(1., 0., 0., 1.);
  table->UseBelowRangeColorOn();
  vtkNew<vtkDataSetSurfaceFilter> kept_surface = boundary(kept);
  vtkNew<vtkPolyDataMapper> kept_mapper;
  kept_mapper->SetInputConnection(kept_surface->GetOutputPort());
  kept_mapper->SetLookupTable(table);
  kept_mapper->SetScalarModeToUseCellData();
  kept_mapper->UseLookupTableScalarRangeOn();
  kept_mapper->ScalarVisibilityOn();
  vtkNew<vtkActor> kept_actor;
  kept_actor->SetMapper(kept_mapper);
  vtkProperty* q = kept_actor->GetProperty();
  q->SetInterpolationToFlat();
  q->EdgeVisibilityOn();
  q->SetEdgeColor(0.15, 0.15, 0.15);
  q->SetAmbient(0.5);   // the colours readable on faces turned away from the light
  q->SetDiffuse(0.5);

  // the layout: two views of the same size side by side, the colour bar in a column of its own
  const double view_width = 0.44, caption_height = 0.14;
  const int font_size = std::max(10, options.height / 40);
  vtkNew<vtkRenderer> left, right, legend;
  left->SetViewport(0., 0., view_width, 1.);
  right->SetViewport(view_width, 0., 2. * view_width, 1.);
  legend->SetViewport(2. * view_width, 0., 1., 1.);
  for(vtkRenderer* r : { left.Get(), right.Get(), legend.Get() }) r->SetBackground(1., 1., 1.);
  left->AddActor(surface_actor);
  right->AddActor(kept_actor);

  vtkNew<vtkScalarBarActor> bar;
  bar->SetLookupTable(table);
  bar->SetTitle("theta_min");
  bar->SetLabelFormat("%.0f");
  vtkNew<vtkDoubleArray> labels;   // 40 50 60 70 (the top is 70.53)
  for(double a = 10. * std::ceil(options.bad_angle / 10.); a <= 70.; a += 10.) labels->InsertNextValue(a);
  bar->SetCustomLabels(labels);
  bar->UseCustomLabelsOn();
  bar->DrawBelowRangeSwatchOn();
  bar->SetBelowRangeAnnotation(("< " + std::to_string(int(std::lround(options.bad_angle)))).c_str());
  bar->UnconstrainedFontSizeOn();
  for(vtkTextProperty* text : { bar->GetTitleTextProperty(), bar->GetLabelTextProperty(), bar->GetAnnotationTextProperty() }) {
    text->SetColor(0.1, 0.1, 0.1);
    text->SetFontSize(font_size);
    text->BoldOff();
    text->ItalicOff();
    text->ShadowOff();
  }
  bar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  bar->GetPositionCoordinate()->SetValue(0.3, 0.1);
  bar->SetWidth(0.65);
  bar->SetHeight(1. - caption_height - 0.1);
  bar->SetMaximumWidthInPixels(int(0.6 * (1. - 2. * view_width) * options.width));
  bar->SetBarRatio(0.3);
  legend->AddActor2D(bar);

  const std::size_t n = tets.size();
  vtkNew<vtkTextActor> left_caption = caption(std::to_string(points.size()) + " vertices, " + std::to_string(n) +
                                              " tetrahedra:\nthe boundary", font_size);
  // the plane's position to a thousandth of the mesh's extent
  const double extent = std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  const double step = extent > 0. ? std::pow(10., std::floor(std::log10(extent)) - 3.) : 1.;
  char plane[64];
  std::snprintf(plane, sizeof(plane), "%.6g", std::round(centre[2] / step) * step + 0.);
  vtkNew<vtkTextActor> right_caption = caption("the tetrahedra with centroid z < " + std::string(plane) + ",\nby theta_min; red: below " +
                                               std::to_string(int(std::lround(options.bad_angle))) + "\xC2\xB0 (" +
                                               std::to_string(bad) + " of " + std::to_string(n) + ")", font_size);
  left->AddActor2D(left_caption);
  right->AddActor2D(right_caption);

  // one oblique camera for both, looking from +z (the side of the cut), from +x and from above;
  // parallel projection, the mesh fitted below the captions
  vtkCamera* camera = left->GetActiveCamera();
  const double direction[3] = { 1.0, 0.8, 1.4 };   // from the focal point to the camera
  double d[3], up[3] = { 0., 1., 0. }, side[3];
  const double norm = std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  for(int i = 0; i < 3; ++i) d[i] = direction[i] / norm;
  const double up_d = up[0] * d[0] + up[1] * d[1] + up[2] * d[2];
  for(int i = 0; i < 3; ++i) up[i] -= up_d * d[i];
  const double up_norm = std::sqrt(up[0] * up[0] + up[1] * up[1] + up[2] * up[2]);
  for(double& x : up) x /= up_norm;
  side[0] = up[1] * d[2] - up[2] * d[1];
  side[1] = up[2] * d[0] - up[0] * d[2];
  side[2] = up[0] * d[1] - up[1] * d[0];
  double u_range[2] = { 0., 0. }, v_range[2] = { 0., 0. };
  for(std::size_t v = 0; v < points.size(); ++v) {
    double u = 0., w = 0.;
    for(std::size_t i = 0; i < 3; ++i) {
      u += (points[v][i] - centre[i]) * side[i];
      w += (points[v][i] - centre[i]) * up[i];
    }
    u_range[0] = v == 0 ? u : std::min(u_range[0], u);
    u_range[1] = v == 0 ? u : std::max(u_range[1], u);
    v_range[0] = v == 0 ? w : std::min(v_range[0], w);
    v_range[1] = v == 0 ? w : std::max(v_range[1], w);
  }
  const double aspect = view_width * options.width / options.height;
  const double half_u = 0.5 * (u_range[1] - u_range[0]), half_v = 0.5 * (v_range[1] - v_range[0]);
  const double scale = 1.05 * std::max({ half_v / (1. - caption_height), half_u / aspect, 1e-12 });
  double focal[3], position[3];
  for(int i = 0; i < 3; ++i) {
    focal[i] = centre[i] + 0.5 * (u_range[0] + u_range[1]) * side[i] + 0.5 * (v_range[0] + v_range[1]) * up[i]
               + caption_height * scale * up[i];   // the mesh below the captions
    position[i] = focal[i] + 2. * (extent > 0. ? extent : 1.) * d[i];
  }
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(focal);
  camera->SetPosition(position);
  camera->SetViewUp(up);
  camera->SetParallelScale(scale);
  right->SetActiveCamera(camera);
  left->ResetCameraClippingRange(bounds);
  right->ResetCameraClippingRange(bounds);

  vtkNew<vtkGenericOpenGLRenderWindow> window;
  window->SetSize(options.width, options.height);
  window->SetOwnContext(0);
  window->SetIsDirect(true);
  window->SetSupportsOpenGL(true);
  window->SetIsCurrent(true);
  window->SetReadyForRendering(true);
  for(vtkRenderer* r : { left.Get(), right.Get(), legend.Get() }) window->AddRenderer(r);
  window->InitializeFromCurrentContext();
  window->Render();

  vtkNew<vtkWindowToImageFilter> image;
  image->SetInput(window);
  image->ReadFrontBufferOff();
  image->ShouldRerenderOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(image->GetOutputPort());
  writer->SetFileName(file.c_str());
  writer->SetCompressionLevel(9);
  writer->Write();
  if(writer->GetErrorCode() != 0) throw std::runtime_error("cannot write '" + file + "'");
}

} // namespace render_png

#endif // LATTICE_MESHER_3_WITH_VTK
