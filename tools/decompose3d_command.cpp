#include "tools/decompose3d_command.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <vector>

#include "acd/check_decomposition3d.h"
#include "acd/decompose3d.h"
#include "acd/decomposition3d.h"
#include "acd/decomposition3d_io.h"
#include "acd/prepare_mesh.h"
#include "base/file_io.h"
#include "base/format.h"
#include "base/input_error.h"
#include "base/stopwatch.h"
#include "envs/mesh_loader.h"
#include "tools/check_report.h"
#include "tools/report_lines.h"

namespace acdplan::tools {
namespace {

namespace fs = std::filesystem;

std::string Lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// The report's "name  value" lines, aligned as the 2D decompose report's.
constexpr ReportLines MeshLine(14);

std::string DefectSummary(const acd::MeshDefects& defects) {
  return Plural(defects.boundary_edges, "boundary edge") + ", " +
         Plural(defects.non_manifold_edges, "non-manifold edge") + ", " +
         Plural(defects.self_intersections, "self-intersecting face pair") +
         (defects.pinch_vertices > 0 ? ", " + Plural(defects.pinch_vertices, "pinch vertex") : "");
}

}  // namespace

std::string MtlPathFor(const std::string& obj_path) {
  return fs::path(obj_path).replace_extension(".mtl").string();
}

int RunDecompose3d(const Decompose3dArguments& args) {
  // Everything the user typed is checked before the (possibly long) decomposition.
  CheckOutputPath("--json", args.json_path);
  CheckOutputPath("--obj", args.obj_path);
  CheckOutputPath("--glb", args.glb_path);
  CheckOutputPath("--svg", args.svg_path);
  const std::string mtl_path = args.obj_path.empty() ? "" : MtlPathFor(args.obj_path);
  if (!args.obj_path.empty()) {
    if (Lower(fs::path(args.obj_path).extension().string()) == ".mtl") {
      throw InputError("--obj " + args.obj_path +
                       ": the material file is written beside the OBJ file with the extension "
                       ".mtl, so the OBJ file cannot have it");
    }
    CheckOutputPath("--obj (material file)", mtl_path);
  }

  const acd::TriangleMesh mesh = envs::ReadMesh(args.input);
  const Stopwatch preparation;
  acd::PrepareMeshOptions prepare_options;
  prepare_options.repair = args.repair;
  const acd::PreparedMesh prepared = acd::PrepareMesh(mesh, prepare_options, args.input);
  const double prepare_ms = preparation.Milliseconds();

  // Solid or surface ACD. An open surface bounds no volume: the surface ACD is the only one
  // that applies. A closed mesh that is not a solid (non-manifold edges, self-intersections)
  // most likely means a modelling error the user should know about: an error unless asked
  // to repair it or to decompose the surface. What --repair cannot mend gets the surface
  // ACD: the user asked for a result, and the report says why it is not the solid one.
  std::string why;
  if (args.surface) {
    why = "surface ACD (--surface)";
  } else if (prepared.solid()) {
    why = "solid ACD (closed, manifold, no self-intersections" +
          std::string(args.repair ? " after --repair)" : ")");
  } else if (args.repair) {
    why = "surface ACD (--repair could not make a solid: " + prepared.defects.first + ")";
  } else if (prepared.defects.boundary_edges > 0) {
    why = "surface ACD (open: " + Plural(prepared.defects.boundary_edges, "boundary edge") +
          "; open meshes get the surface ACD)";
  } else {
    acd::RequireSolid(prepared, args.input);  // Throws, naming the defect and the way out.
  }

  const double radius = acd::ReferenceRadius(prepared.mesh);
  const double tau_rel = args.tau >= 0 ? -1.0 : args.tau_rel >= 0 ? args.tau_rel : kDefaultTauRel3d;
  acd::Decompose3dOptions options;
  options.tau = args.tau >= 0 ? args.tau : tau_rel * radius;
  options.surface = args.surface;
  options.max_hulls = args.max_hulls;
  options.merge_growth = args.merge_growth;
  const acd::Decomposition3d decomposition = acd::Decompose3d(prepared, options);

  if (args.check) {
    const acd::DecompositionCheck check = acd::CheckDecomposition3d(prepared, decomposition);
    if (!check.ok()) return ReportFailedCheck(args.input, check);
  }

  // Every output is produced in memory first and written atomically, so a failure leaves no
  // partial file behind.
  acd::DecompositionLabels labels;
  labels.input = args.input;
  labels.tau_rel = tau_rel;
  std::vector<std::string> written;
  auto write = [&written](const std::string& path, const std::string& text) {
    WriteFileAtomically(path, text);
    written.push_back(path);
  };
  try {
    if (!args.json_path.empty()) {
      write(args.json_path, acd::Decomposition3dToJson(decomposition, labels));
    }
    if (!args.obj_path.empty()) {
      const acd::ObjFiles files =
          acd::Decomposition3dToObj(decomposition, fs::path(mtl_path).filename().string());
      write(mtl_path, files.mtl);  // First, so the OBJ never refers to a missing file.
      write(args.obj_path, files.obj);
    }
    if (!args.glb_path.empty()) {
      const std::vector<std::uint8_t> glb = acd::Decomposition3dToGlb(decomposition);
      write(args.glb_path, std::string(glb.begin(), glb.end()));
    }
    if (!args.svg_path.empty()) {
      write(args.svg_path, acd::Decomposition3dToSvg(decomposition, labels));
    }
  } catch (const std::runtime_error& error) {
    throw InputError(error.what());  // The user's path to fix: exit status 2.
  }

  const acd::DecompositionStats3d& stats = decomposition.stats;
  MeshLine("input", args.input + " (" + Plural(mesh.vertices.rows(), "vertex") + ", " +
                        Plural(mesh.triangles.rows(), "triangle") + ")");
  MeshLine("prepared", Plural(prepared.mesh.vertices.rows(), "vertex") + ", " +
                           Plural(prepared.mesh.triangles.rows(), "triangle") + ", " +
                           Plural(prepared.parts.size(), "part") + ", " +
                           FormatSignificant(prepare_ms, 3) + " ms");
  for (const std::string& note : prepared.notes) MeshLine("  changed", note);
  if (prepared.defects.none()) {
    MeshLine("defects", "none");
  } else {
    MeshLine("defects", DefectSummary(prepared.defects));
    MeshLine("  first", prepared.defects.first);
  }
  MeshLine("acd", why);
  if (tau_rel >= 0) {
    MeshLine("tau", ReportNumber(decomposition.tau) + " (tau_rel " + ReportNumber(tau_rel) +
                        " x radius " + ReportNumber(radius) +
                        (args.tau_rel < 0 ? ", the default)" : ")"));
  } else {
    MeshLine("tau", ReportNumber(decomposition.tau));
  }
  if (decomposition.max_hulls > 0) MeshLine("max hulls", std::to_string(decomposition.max_hulls));
  if (decomposition.merge_growth >= 0) {
    MeshLine("merge",
             "tau-convex neighbours, hull growth <= " + ReportNumber(decomposition.merge_growth));
  }
  MeshLine("components", std::to_string(stats.components));
  if (stats.surface) {
    MeshLine("hull volume", ReportNumber(stats.hull_volume));
  } else {
    MeshLine("hull volume",
             ReportNumber(stats.hull_volume) + " / volume " + ReportNumber(stats.volume) + " = " +
                 (stats.volume > 0 ? ReportNumber(stats.hull_volume / stats.volume) : "n/a"));
  }
  MeshLine("max concavity", ReportNumber(stats.max_concavity));
  MeshLine("time", FormatFixed(stats.time_ms, 3) + " ms");
  if (args.check) MeshLine("check", "ok");
  for (const std::string& path : written) MeshLine("wrote", path);
  return 0;
}

}  // namespace acdplan::tools
