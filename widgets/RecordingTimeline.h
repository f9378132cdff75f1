#pragma once
// The Recorder dock's timeline: the tick range of a recording, a handle to scrub with (click, drag,
// arrows, PageUp/PageDown, Home/End, Ctrl+arrows to the previous/next marker), the recording's
// events as coloured markers above the track, and the stretches a replay cannot show (gaps, damage,
// past the replayable end) in red over it. Tooltips name the event or the stretch and its time.
// It only shows a position and reports the user's moves; the panel owns the player.

#include <QString>
#include <QWidget>

#include <cstdint>
#include <functional>
#include <vector>

namespace palpate {

class RecordingTimeline final : public QWidget {
    Q_OBJECT
public:
    /// What a marker stands for: each has its own colour (legend in the tooltip).
    enum class MarkerKind { Mark, Parameters, Scene, Device, Pause, Problem };
    struct Marker {
        std::uint64_t tick = 0;
        MarkerKind kind = MarkerKind::Mark;
        QString text;  ///< "Mark: palpated the nodule" (translated by whoever makes it)
    };
    /// A stretch the replay cannot show: ticks dropped (gap), lost to damage, or past a replay stop.
    struct Region {
        std::uint64_t firstTick = 0, lastTick = 0;
        QString text;
    };

    explicit RecordingTimeline(QWidget* parent = nullptr);

    /// The ticks the track spans (first < last, else one tick wide). Clamps the value into it.
    void setRange(std::uint64_t firstTick, std::uint64_t lastTick);
    std::uint64_t firstTick() const { return mFirst; }
    std::uint64_t lastTick() const { return mLast; }
    /// Moves the handle without emitting scrubbed (the player's position).
    void setValue(std::uint64_t tick);
    std::uint64_t value() const { return mValue; }
    /// Ticks per arrow key and per PageUp/PageDown.
    void setSingleStep(std::uint64_t ticks) { mSingleStep = ticks > 0 ? ticks : 1; }
    void setPageStep(std::uint64_t ticks) { mPageStep = ticks > 0 ? ticks : 1; }
    std::uint64_t singleStep() const { return mSingleStep; }
    std::uint64_t pageStep() const { return mPageStep; }
    /// Loop time (s, from the start) of a tick, for tooltips; without it, ticks are shown.
    void setTimeOfTick(std::function<double(std::uint64_t)> timeOfTick) { mTimeOfTick = std::move(timeOfTick); }

    void setMarkers(std::vector<Marker> markers);
    void setRegions(std::vector<Region> regions);
    const std::vector<Marker>& markers() const { return mMarkers; }
    const std::vector<Region>& regions() const { return mRegions; }
    /// Empties the timeline (no recording open).
    void clear();

    /// What the tooltip says at `pos` (widget coordinates): the markers near it, else the stretch
    /// under it, else the time there.
    QString toolTipAt(QPoint pos) const;
    /// Where a tick is drawn (x, widget coordinates) and the tick at an x.
    int xOfTick(std::uint64_t tick) const;
    std::uint64_t tickAtX(int x) const;

    /// "1:02.345" (m:ss.mmm; h:mm:ss.mmm from an hour on).
    static QString formatTime(double seconds);
    static QColor markerColour(MarkerKind kind);

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

signals:
    /// The user moved the handle (mouse or keyboard) to `tick`.
    void scrubbed(quint64 tick);
    /// Space while the timeline has focus (the window's Space pauses the live session instead).
    void playPauseRequested();

protected:
    bool event(QEvent* event) override;
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    QRect trackRect() const;
    void userMove(std::uint64_t tick);
    QString tickText(std::uint64_t tick) const;
    /// Markers drawn within `radiusPx` of x.
    std::vector<const Marker*> markersNear(int x, int radiusPx) const;

    std::uint64_t mFirst = 0, mLast = 0, mValue = 0;
    std::uint64_t mSingleStep = 1, mPageStep = 100;
    std::vector<Marker> mMarkers;  // sorted by tick
    std::vector<Region> mRegions;
    std::function<double(std::uint64_t)> mTimeOfTick;
    bool mDragging = false;
    bool mEmpty = true;
};

}  // namespace palpate
