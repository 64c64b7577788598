// Placeholder so the GUI library has a source until its widgets land.
#pragma once
