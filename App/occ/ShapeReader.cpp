#include "occ/ShapeReader.hpp"
