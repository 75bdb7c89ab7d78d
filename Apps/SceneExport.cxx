// Scene export (see SceneExport.h).
#include "SceneExport.h"

#include "AMRIntake.h"
#include "io/SceneFile.h"
#include "mesh/PrepareHierarchy.h"

#include <cstdio>
#include <cstring>
#include <sys/stat.h>

namespace amrdm_app
{

bool ExportScene(const std::string& path,
  const std::string& name,
  vtkOverlappingAMR* amr,
  const std::string& array,
  int component,
  bool logScale,
  int gridletSize,
  int bvhLeafSize,
  const amrdm::RenderParams& params,
  const amrdm::TransferFunction& tf,
  std::string& error)
{
  amrdm::SceneDescription scene;
  scene.name = name;
  amrdm::LevelBoxes metadata;
  if (!amrdm_vtk::ConvertAMR(amr,
        array.c_str(),
        component,
        logScale,
        scene.hierarchy,
        error,
        0,
        amrdm::FieldAssociation::Cells,
        &metadata))
    return false;
  scene.gridletSize = gridletSize;
  scene.bvhLeafSize = bvhLeafSize;
  scene.tf = tf;
  scene.params = params;
  scene.params.threads = 0;
  try
  {
    amrdm::checkHierarchy(scene.hierarchy, &metadata); // the pipeline's checks, as the mapper's
    amrdm::writeSceneFile(path, scene);
  }
  catch (const std::exception& e)
  {
    error = e.what();
    return false;
  }
  struct stat st;
  const double mb = stat(path.c_str(), &st) == 0 ? double(st.st_size) / 1e6 : 0.0;
  std::printf("wrote scene %s (%s; %.2f MB, %zu blocks)\n",
    path.c_str(),
    name.c_str(),
    mb,
    scene.hierarchy.blocks.size());
  return true;
}

} // namespace amrdm_app
