#include "acd/read_polygons.h"
