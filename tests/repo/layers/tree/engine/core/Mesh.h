#pragma once
// An engine header the device fixture includes.
