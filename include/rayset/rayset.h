// rayset's whole public API in one include: ray files (rays.h), photometry and far fields
// (photometry.h), light-source models and their emitter interface (model.h), scene rendering
// (render.h). Link rayset::tracer, which brings the other libraries. docs/api.md lists every
// name; the other headers installed under include/rayset/ are internal and may change.
#pragma once

#include <rayset/model.h>
#include <rayset/photometry.h>
#include <rayset/rays.h>
#include <rayset/render.h>
