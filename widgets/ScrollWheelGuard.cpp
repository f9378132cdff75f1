#include "widgets/ScrollWheelGuard.h"

#include <QAbstractSpinBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QEvent>
#include <QScrollArea>

namespace palpate {

namespace {

bool isValueField(const QObject* object) {
    return qobject_cast<const QAbstractSpinBox*>(object) || qobject_cast<const QComboBox*>(object);
}

class WheelToScrollArea final : public QObject {
public:
    explicit WheelToScrollArea(QScrollArea& scroll) : QObject(&scroll), mScroll(scroll) {}

    bool eventFilter(QObject* watched, QEvent* event) override {
        if (event->type() == QEvent::Wheel && isValueField(watched) && !static_cast<QWidget*>(watched)->hasFocus()) {
            QCoreApplication::sendEvent(mScroll.viewport(), event);  // the form scrolls instead
            return true;
        }
        return false;
    }

private:
    QScrollArea& mScroll;
};

}  // namespace

void guardScrollWheel(QScrollArea& scroll) {
    if (!scroll.widget()) return;
    auto* guard = new WheelToScrollArea(scroll);
    for (QWidget* field : scroll.widget()->findChildren<QWidget*>())
        if (isValueField(field)) {
            field->setFocusPolicy(Qt::StrongFocus);
            field->installEventFilter(guard);
        }
}

}  // namespace palpate
