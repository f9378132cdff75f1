#include "widgets/WelcomePage.h"

#include <QCheckBox>
#include <QCommandLinkButton>
#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QIcon>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace palpate {

WelcomePage::WelcomePage(QWidget* parent) : QDialog(parent) {
    setObjectName(QStringLiteral("welcomePage"));
    setWindowTitle(tr("Welcome to Palpate"));

    auto* title = new QLabel(tr("<h2>Welcome to Palpate</h2>"), this);
    title->setObjectName(QStringLiteral("welcomeTitle"));
    auto* intro = new QLabel(tr("Palpate lets you feel a soft tissue model through a haptic device, or with the "
                                "mouse. Here are four things to try first; you find this page again under "
                                "Help > Welcome, and the user guide under Help > User Guide (F1)."),
                             this);
    intro->setObjectName(QStringLiteral("welcomeIntro"));
    intro->setWordWrap(true);

    auto* logo = new QLabel(this);
    logo->setObjectName(QStringLiteral("welcomeLogo"));
    logo->setPixmap(QIcon(QStringLiteral(":/icons/palpate-64.png")).pixmap(64, 64));
    auto* header = new QHBoxLayout;
    header->addWidget(logo);
    header->addWidget(title, 1);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(header);
    layout->addWidget(intro);
    layout->addSpacing(8);
    mActions = new QVBoxLayout;
    mActions->setSpacing(4);
    layout->addLayout(mActions);

    mSampleScene = addAction(QStringLiteral("welcomeSampleScene"), tr("Open the sample scene"),
                             tr("The stomach wall model with its default tissue, ready to be pressed."),
                             &WelcomePage::sampleSceneRequested);
    mTouchMode = addAction(QStringLiteral("welcomeTouchMode"), tr("Try touch mode with the mouse"),
                           tr("Left-drag presses the tissue, the wheel sets the depth; right-drag turns the "
                              "view. No haptic device needed."),
                           &WelcomePage::touchModeRequested);
    mExercise = addAction(QStringLiteral("welcomeExercise"), tr("Run the example exercise"),
                          tr("\"Press three targets\" as a preview: the Exercise dock guides you and scores the "
                             "run (nothing is stored)."),
                          &WelcomePage::exerciseRequested);
    mUserGuide = addAction(QStringLiteral("welcomeUserGuide"), tr("Read the user guide"),
                           tr("What every window, dock and menu does, with pictures."), &WelcomePage::userGuideRequested);

    mDontShow = new QCheckBox(tr("&Don't show this again at start"), this);
    mDontShow->setObjectName(QStringLiteral("welcomeDontShow"));
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &WelcomePage::reject);
    auto* bottom = new QHBoxLayout;
    bottom->addWidget(mDontShow, 1);
    bottom->addWidget(buttons);
    layout->addStretch(1);
    layout->addLayout(bottom);
    setMinimumWidth(560);
    resize(600, heightForWidth(600) > 0 ? heightForWidth(600) : sizeHint().height());
}

QCommandLinkButton* WelcomePage::addAction(const QString& objectName, const QString& text, const QString& description,
                                           void (WelcomePage::*request)()) {
    auto* button = new QCommandLinkButton(text, description, this);
    button->setObjectName(objectName);
    mActions->addWidget(button);
    connect(button, &QCommandLinkButton::clicked, this, [this, request] {
        emit(this->*request)();
        accept();
    });
    return button;
}

bool WelcomePage::dontShowAgain() const { return mDontShow->isChecked(); }

void WelcomePage::setDontShowAgain(bool on) { mDontShow->setChecked(on); }

}  // namespace palpate
