#pragma once
#define RT_VERSION "0.1.0"
