#pragma once
// In a scrolling form, the wheel scrolls the form: a spin box or combo that passes under the
// cursor while the user scrolls is not changed. It takes the wheel once clicked or tabbed into.

class QScrollArea;

namespace palpate {

/// Guards every spin box and combo now inside `scroll`'s widget (the guard is the scroll area's
/// child, so it lives as long as the form).
void guardScrollWheel(QScrollArea& scroll);

}  // namespace palpate
