#pragma once
// Stands for a scene header (the layering test's fixture).
