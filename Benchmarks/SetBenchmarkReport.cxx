// SetBenchmark: the set's facts (memory, counts, reference settings) for results.json, the
// scene (camera, transfer function, reference) for Benchmarks/paraview_volume.py, and the files.
#include "SetBenchmark.h"

#include "AMRDualMeshVTKCompat.h"

#include <fstream>

namespace amrdm_bench
{

namespace
{

using Json = nlohmann::ordered_json;

Json vec3(const glm::dvec3& v)
{
  return Json::array({ jsonValue(v.x), jsonValue(v.y), jsonValue(v.z) });
}

Json ivec3(const glm::ivec3& v)
{
  return Json::array({ v.x, v.y, v.z });
}

} // namespace

void SetBenchmark::setFacts()
{
  vtkAMRDualMesh* field = this->scene.field;
  Json j;
  j["name"] = this->spec.name;
  j["path"] = this->spec.path;
  j["array"] = this->spec.array;
  j["log_scale"] = this->spec.logScale;
  j["read_s"] = jsonValue(this->scene.readSeconds);
  j["finest_dims"] = ivec3(this->scene.finestDims);
  j["levels"] = amrdm_vtk::amrcompat::NumberOfLevels(this->scene.amr);
  j["dual_mesh"] = Json::parse(field->GetReportJSON());
  j["perfect_cubes"] = field->GetNumberOfPerfectCubes();
  j["elements"] = field->GetNumberOfTets() + field->GetNumberOfPyramids() +
                  field->GetNumberOfWedges() + field->GetNumberOfHexes();
  j["majorant_default"] = ivec3(this->defaultRes);
  j["majorant_bytes"] = this->base->majorants.bytes();
  j["culling_bytes"] = this->base->cullingBytes();
  j["nearest_bytes"] = this->nearest.bytes();
  j["gridlets"] = this->gridlets;
  j["bvh_leaves"] = this->bvhLeaves;
  j["pt_ref_spp"] = this->refSpp;
  j["pt_ref_s"] = jsonValue(this->ptRefSeconds);
  j["pt_ref_noise"] = jsonValue(this->refNoise);
  j["pt_frames"] = this->K;
  j["rm_base_step"] = jsonValue(this->hBase);
  j["rm_ref_step"] = jsonValue(this->hBase / 4.0);
  j["rm_ref_spp"] = this->rmRefSpp;
  j["rm_ref_s"] = jsonValue(this->rmRefSeconds);
  j["set_s"] = jsonValue(seconds(this->start));
  this->o.sets.push_back(j);
}

void SetBenchmark::sceneForParaView()
{
  const amrdm::CameraParams& cam = this->scene.params.camera;
  const amrdm::TransferFunction& tf = this->scene.tf;
  Json j;
  j["name"] = this->spec.name;
  j["path"] = this->spec.path;
  j["reader"] = this->spec.reader;
  j["array"] = this->spec.array;
  j["log_scale"] = this->spec.logScale;
  j["width"] = this->mode.width;
  j["height"] = this->mode.height;
  j["camera"]["position"] = vec3(glm::dvec3(cam.position) + this->scene.sceneOrigin);
  j["camera"]["focal_point"] = vec3(glm::dvec3(this->scene.focalPoint) + this->scene.sceneOrigin);
  j["camera"]["view_up"] = vec3(cam.up);
  j["camera"]["view_angle"] = jsonValue(cam.viewAngle);
  j["tf"]["lo"] = jsonValue(tf.lo);
  j["tf"]["hi"] = jsonValue(tf.hi);
  j["tf"]["unit_distance"] = jsonValue(tf.unitDistance);
  Json table = Json::array();
  for (const auto& c : tf.table)
    table.push_back(
      Json::array({ jsonValue(c.x), jsonValue(c.y), jsonValue(c.z), jsonValue(c.w) }));
  j["tf"]["table"] = table;
  j["finest_dims"] = ivec3(this->scene.finestDims);
  j["reference"] = this->out + "/ref-rm-" + this->spec.name + ".f32";
  this->o.scenes.push_back(j);
}

void writeResults(const std::string& out, const Mode& mode, const Outputs& o, double totalSeconds)
{
  std::ofstream f(out + "/results.json");
  f << "{\"mode\": \"" << (mode.quick ? "quick" : "full") << "\", \"width\": " << mode.width
    << ", \"height\": " << mode.height << ", \"total_s\": " << jsonNumber(totalSeconds)
    << ",\n\"sets\": [";
  for (std::size_t i = 0; i < o.sets.size(); ++i)
    f << (i ? ",\n" : "\n") << dumpJson(o.sets[i]);
  f << "\n],\n\"rows\": " << jsonArray(o.rows) << ",\n\"curves\": " << jsonArray(o.curves) << "}\n";
  std::ofstream s(out + "/scenes.json");
  s << "[";
  for (std::size_t i = 0; i < o.scenes.size(); ++i)
    s << (i ? ",\n" : "\n") << dumpJson(o.scenes[i]);
  s << "\n]\n";
}

} // namespace amrdm_bench
