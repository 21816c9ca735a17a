#pragma once
// Writes what cosim identify found: FILE.yaml (the airframe parameters a scenario's
// vehicles[i].airframe reads, each with its interval, residual and sample count), FILE.md (a
// short report) and one figure per fit, FILE.<fit>.png and .svg (gnuplot, as render/ draws).
// Every file is written atomically; an existing FILE.yaml or FILE.md is replaced only if cosim
// identify wrote it (its first line says so), else InputError before anything is written.
#include <filesystem>

#include "experiments/identify/identification.h"

namespace cosim {

// The first line of every FILE.yaml cosim identify writes.
inline constexpr const char* kIdentifiedYamlHeader = "# cosim identify: airframe parameters";

void checkIdentificationOutput(const std::filesystem::path& yaml_path);
void writeIdentification(const std::filesystem::path& yaml_path, const IdentificationResult& r,
                         const IdentifyOptions& options);
// The YAML text alone (the report and figures aside).
std::string identificationYaml(const IdentificationResult& r, const IdentifyOptions& options);

}  // namespace cosim
