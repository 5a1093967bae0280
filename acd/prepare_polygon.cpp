#include "acd/prepare_polygon.h"
