#include "acd/internal/triangulate_ring.h"
