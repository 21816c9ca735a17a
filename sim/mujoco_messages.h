#pragma once
// MuJoCo's warnings and errors go to cosim's stderr instead of MuJoCo's defaults, which print
// to stdout, append to MUJOCO_LOG.TXT in the current folder, and, for an error, exit(1) (the
// "task failed" exit status). Simulation loops still see each warning in mjData's
// warning counters, as before.
namespace cosim {

// Installs the handlers where none is installed (a test may have installed its own).
// A warning becomes one stderr line "cosim: mujoco: TEXT". An error (MuJoCo cannot go on; its
// handler must not return) becomes "cosim: internal error: mujoco: TEXT" and exit status 3.
void installMujocoMessageHandlers();

}  // namespace cosim
