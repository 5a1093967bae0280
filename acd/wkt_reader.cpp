#include "acd/wkt_reader.h"
