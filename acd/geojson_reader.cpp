#include "acd/geojson_reader.h"
