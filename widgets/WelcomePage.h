#pragma once
// The welcome page: shown at the first start (until "Don't show this again") and from Help >
// Welcome. Three things to try, each a request the main window answers (app/gui/FirstRun.cpp):
// the sample scene, touch mode with the mouse, the example exercise; and the user guide.

#include <QDialog>

class QCheckBox;
class QCommandLinkButton;
class QVBoxLayout;

namespace palpate {

class WelcomePage final : public QDialog {
    Q_OBJECT
public:
    explicit WelcomePage(QWidget* parent = nullptr);

    /// "Don't show this again" is ticked.
    bool dontShowAgain() const;
    void setDontShowAgain(bool on);

    QCommandLinkButton* sampleSceneButton() const { return mSampleScene; }
    QCommandLinkButton* touchModeButton() const { return mTouchMode; }
    QCommandLinkButton* exerciseButton() const { return mExercise; }
    QCommandLinkButton* userGuideButton() const { return mUserGuide; }
    QCheckBox* dontShowAgainBox() const { return mDontShow; }

signals:
    /// Each button emits its request, then the page closes (accepted).
    void sampleSceneRequested();
    void touchModeRequested();
    void exerciseRequested();
    void userGuideRequested();

private:
    QCommandLinkButton* addAction(const QString& objectName, const QString& text, const QString& description,
                                  void (WelcomePage::*request)());

    QCommandLinkButton* mSampleScene = nullptr;
    QCommandLinkButton* mTouchMode = nullptr;
    QCommandLinkButton* mExercise = nullptr;
    QCommandLinkButton* mUserGuide = nullptr;
    QCheckBox* mDontShow = nullptr;
    QVBoxLayout* mActions = nullptr;
};

}  // namespace palpate
