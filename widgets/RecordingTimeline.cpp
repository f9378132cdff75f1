#include "widgets/RecordingTimeline.h"

#include <QHelpEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>

#include <algorithm>
#include <cmath>

namespace palpate {

namespace {

constexpr int kSideMarginPx = 9;     ///< room for the handle at both ends
constexpr int kMarkerLaneTopPx = 2;
constexpr int kMarkerHeightPx = 9;
constexpr int kTrackTopPx = 15;
constexpr int kTrackHeightPx = 10;
constexpr int kHandleRadiusPx = 7;
constexpr int kHeightPx = kTrackTopPx + kTrackHeightPx + kHandleRadiusPx - 2;
constexpr int kNearPx = 4;           ///< how close the mouse must be to a marker for its tooltip or snap
constexpr int kMaxTooltipMarkers = 6;

}  // namespace

RecordingTimeline::RecordingTimeline(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("recordingTimeline"));
    setFocusPolicy(Qt::StrongFocus);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    setAccessibleName(tr("Recording timeline"));
    setAccessibleDescription(tr("Arrows step, Page Up and Page Down jump, Home and End go to the ends, Ctrl+arrows go "
                                "to the previous or next event, Space plays or pauses"));
    setMouseTracking(false);
    clear();
}

void RecordingTimeline::clear() {
    mEmpty = true;
    mFirst = mLast = mValue = 0;
    mMarkers.clear();
    mRegions.clear();
    mTimeOfTick = nullptr;
    setToolTip(tr("Open a recording to scrub through it"));
    update();
}

void RecordingTimeline::setRange(std::uint64_t firstTick, std::uint64_t lastTick) {
    mEmpty = false;
    mFirst = firstTick;
    mLast = std::max(lastTick, firstTick);
    mValue = std::clamp(mValue, mFirst, mLast);
    setToolTip(QString());  // from here on the tooltip follows the mouse (event())
    update();
}

void RecordingTimeline::setValue(std::uint64_t tick) {
    tick = std::clamp(tick, mFirst, mLast);
    if (tick == mValue) return;
    mValue = tick;
    update();
}

void RecordingTimeline::setMarkers(std::vector<Marker> markers) {
    std::stable_sort(markers.begin(), markers.end(), [](const Marker& a, const Marker& b) { return a.tick < b.tick; });
    mMarkers = std::move(markers);
    update();
}

void RecordingTimeline::setRegions(std::vector<Region> regions) {
    mRegions = std::move(regions);
    update();
}

QRect RecordingTimeline::trackRect() const {
    return QRect(kSideMarginPx, kTrackTopPx, std::max(1, width() - 2 * kSideMarginPx), kTrackHeightPx);
}

int RecordingTimeline::xOfTick(std::uint64_t tick) const {
    const QRect track = trackRect();
    if (mLast <= mFirst) return track.left();
    const double f = double(std::clamp(tick, mFirst, mLast) - mFirst) / double(mLast - mFirst);
    return track.left() + int(std::lround(f * double(track.width() - 1)));
}

std::uint64_t RecordingTimeline::tickAtX(int x) const {
    const QRect track = trackRect();
    if (mLast <= mFirst || track.width() <= 1) return mFirst;
    const double f = std::clamp(double(x - track.left()) / double(track.width() - 1), 0.0, 1.0);
    return mFirst + std::uint64_t(std::llround(f * double(mLast - mFirst)));
}

QString RecordingTimeline::formatTime(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0.0) seconds = 0.0;
    const auto ms = std::int64_t(std::llround(seconds * 1000.0));
    const std::int64_t h = ms / 3'600'000, m = (ms / 60'000) % 60, s = (ms / 1000) % 60, rest = ms % 1000;
    const QString tail = QStringLiteral("%1.%2").arg(s, 2, 10, QLatin1Char('0')).arg(rest, 3, 10, QLatin1Char('0'));
    if (h > 0) return QStringLiteral("%1:%2:%3").arg(h).arg(m, 2, 10, QLatin1Char('0')).arg(tail);
    return QStringLiteral("%1:%2").arg(m).arg(tail);
}

QColor RecordingTimeline::markerColour(MarkerKind kind) {
    switch (kind) {
        case MarkerKind::Mark: return QColor(0xf9, 0xa8, 0x25);        // amber: the user's marks
        case MarkerKind::Parameters: return QColor(0x1e, 0x88, 0xe5);  // blue
        case MarkerKind::Scene: return QColor(0x8e, 0x24, 0xaa);       // purple
        case MarkerKind::Device: return QColor(0x00, 0x89, 0x7b);      // teal
        case MarkerKind::Pause: return QColor(0x75, 0x75, 0x75);       // grey
        case MarkerKind::Problem: return QColor(0xe5, 0x39, 0x35);     // red, as the damaged stretches
    }
    return Qt::black;
}

QString RecordingTimeline::tickText(std::uint64_t tick) const {
    if (mTimeOfTick) return tr("%1 (tick %2)").arg(formatTime(mTimeOfTick(tick))).arg(tick);
    return tr("tick %1").arg(tick);
}

std::vector<const RecordingTimeline::Marker*> RecordingTimeline::markersNear(int x, int radiusPx) const {
    std::vector<const Marker*> near;
    for (const Marker& m : mMarkers)
        if (std::abs(xOfTick(m.tick) - x) <= radiusPx) near.push_back(&m);
    return near;
}

QString RecordingTimeline::toolTipAt(QPoint pos) const {
    if (mEmpty) return tr("Open a recording to scrub through it");
    const auto near = markersNear(pos.x(), kNearPx);
    if (!near.empty()) {
        QStringList lines;
        for (std::size_t i = 0; i < near.size() && int(i) < kMaxTooltipMarkers; ++i)
            lines << tr("%1 at %2").arg(near[i]->text, tickText(near[i]->tick));
        if (int(near.size()) > kMaxTooltipMarkers) lines << tr("… and %1 more here").arg(int(near.size()) - kMaxTooltipMarkers);
        return lines.join(QLatin1Char('\n'));
    }
    const std::uint64_t tick = tickAtX(pos.x());
    for (const Region& r : mRegions)
        if (std::abs(pos.x() - std::clamp(pos.x(), xOfTick(r.firstTick), xOfTick(r.lastTick))) <= 1)
            return tr("%1: ticks %2 to %3").arg(r.text).arg(r.firstTick).arg(r.lastTick);
    return tickText(tick);
}

bool RecordingTimeline::event(QEvent* event) {
    if (event->type() == QEvent::ToolTip) {
        auto* help = static_cast<QHelpEvent*>(event);
        QToolTip::showText(help->globalPos(), toolTipAt(help->pos()), this);
        return true;
    }
    if (event->type() == QEvent::ShortcutOverride) {
        // Space plays the recording here; the window's Space (pause the live session) must not fire.
        auto* key = static_cast<QKeyEvent*>(event);
        if (key->key() == Qt::Key_Space && key->modifiers() == Qt::NoModifier) {
            event->accept();
            return true;
        }
    }
    return QWidget::event(event);
}

void RecordingTimeline::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QRect track = trackRect();
    const QPalette& pal = palette();

    // The track and, up to the handle, the part already played.
    p.setPen(QPen(pal.color(QPalette::Mid), 1));
    p.setBrush(pal.color(isEnabled() ? QPalette::Base : QPalette::Window));
    p.drawRoundedRect(QRectF(track).adjusted(0.5, 0.5, -0.5, -0.5), 3, 3);
    if (mEmpty) return;
    const int handleX = xOfTick(mValue);
    if (handleX > track.left()) {
        QColor played = pal.color(QPalette::Highlight);
        played.setAlpha(isEnabled() ? 150 : 60);
        p.setPen(Qt::NoPen);
        p.setBrush(played);
        p.drawRoundedRect(QRectF(track.left() + 1, track.top() + 1, handleX - track.left(), track.height() - 2), 2, 2);
    }

    // What the replay cannot show, in red over the track.
    QColor lost = markerColour(MarkerKind::Problem);
    lost.setAlpha(200);
    for (const Region& r : mRegions) {
        const int x0 = xOfTick(r.firstTick), x1 = std::max(xOfTick(r.lastTick), x0 + 2);
        p.fillRect(QRect(x0, track.top(), x1 - x0 + 1, track.height()), QBrush(lost));
    }

    // Events: a small downward triangle above the track and a faint line across it.
    for (const Marker& m : mMarkers) {
        const int x = xOfTick(m.tick);
        const QColor c = markerColour(m.kind);
        QPainterPath tri;
        tri.moveTo(x - 4.5, kMarkerLaneTopPx);
        tri.lineTo(x + 4.5, kMarkerLaneTopPx);
        tri.lineTo(x, kMarkerLaneTopPx + kMarkerHeightPx);
        tri.closeSubpath();
        p.setPen(QPen(c.darker(130), 1));
        p.setBrush(c);
        p.drawPath(tri);
        p.setPen(QPen(c, 1));
        p.drawLine(QPointF(x + 0.5, track.top() + 1), QPointF(x + 0.5, track.bottom()));
    }

    // The handle, with a focus ring when the keys move it.
    const QPointF centre(handleX + 0.5, track.center().y() + 0.5);
    if (hasFocus()) {
        p.setPen(QPen(pal.color(QPalette::Highlight), 2));
        p.setBrush(Qt::NoBrush);
        p.drawEllipse(centre, kHandleRadiusPx + 1.5, kHandleRadiusPx + 1.5);
    }
    p.setPen(QPen(pal.color(QPalette::Dark), 1));
    p.setBrush(pal.color(QPalette::Button));
    p.drawEllipse(centre, kHandleRadiusPx - 0.5, kHandleRadiusPx - 0.5);
    p.setPen(QPen(pal.color(QPalette::Highlight), 2));
    p.drawLine(QPointF(centre.x(), centre.y() - 3), QPointF(centre.x(), centre.y() + 3));
}

void RecordingTimeline::userMove(std::uint64_t tick) {
    tick = std::clamp(tick, mFirst, mLast);
    const bool moved = tick != mValue;
    mValue = tick;
    update();
    if (moved) emit scrubbed(tick);
}

void RecordingTimeline::mousePressEvent(QMouseEvent* event) {
    if (mEmpty || event->button() != Qt::LeftButton) return QWidget::mousePressEvent(event);
    mDragging = true;
    const int x = int(event->position().x());
    // A click on a marker goes to its tick exactly.
    const auto near = markersNear(x, kNearPx);
    userMove(near.empty() ? tickAtX(x) : near.front()->tick);
    event->accept();
}

void RecordingTimeline::mouseMoveEvent(QMouseEvent* event) {
    if (!mDragging) return QWidget::mouseMoveEvent(event);
    userMove(tickAtX(int(event->position().x())));
    event->accept();
}

void RecordingTimeline::mouseReleaseEvent(QMouseEvent* event) {
    if (!mDragging) return QWidget::mouseReleaseEvent(event);
    mDragging = false;
    event->accept();
}

void RecordingTimeline::keyPressEvent(QKeyEvent* event) {
    if (mEmpty) return QWidget::keyPressEvent(event);
    const bool ctrl = event->modifiers() & Qt::ControlModifier;
    auto back = [this](std::uint64_t by) { return mValue - std::min(by, mValue - mFirst); };
    auto ahead = [this](std::uint64_t by) { return mValue + std::min(by, mLast - mValue); };
    switch (event->key()) {
        case Qt::Key_Left:
        case Qt::Key_Down:
            if (ctrl) {  // the previous event
                std::uint64_t target = mFirst;
                for (const Marker& m : mMarkers)
                    if (m.tick < mValue) target = m.tick;
                userMove(target);
            } else {
                userMove(back(mSingleStep));
            }
            break;
        case Qt::Key_Right:
        case Qt::Key_Up:
            if (ctrl) {  // the next event
                std::uint64_t target = mLast;
                for (const Marker& m : mMarkers)
                    if (m.tick > mValue) {
                        target = m.tick;
                        break;
                    }
                userMove(target);
            } else {
                userMove(ahead(mSingleStep));
            }
            break;
        case Qt::Key_PageDown: userMove(back(mPageStep)); break;
        case Qt::Key_PageUp: userMove(ahead(mPageStep)); break;
        case Qt::Key_Home: userMove(mFirst); break;
        case Qt::Key_End: userMove(mLast); break;
        case Qt::Key_Space: emit playPauseRequested(); break;
        default: return QWidget::keyPressEvent(event);
    }
    event->accept();
}

QSize RecordingTimeline::sizeHint() const { return {360, kHeightPx}; }

QSize RecordingTimeline::minimumSizeHint() const { return {120, kHeightPx}; }

}  // namespace palpate
