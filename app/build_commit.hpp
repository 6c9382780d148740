#pragma once
// The commit the program was built from (git rev-parse --short=12 HEAD at build time),
// "+dirty" when tracked files differed from it, "unknown" outside a checkout. Results
// files carry it so that a published number names what measured it.

namespace antumbra::app {

const char* build_commit();

}  // namespace antumbra::app
