#include "widgets/StiffeningPanel.h"

#include "results/HandOff.h"

#include <QChart>
#include <QChartView>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineSeries>
#include <QProgressBar>
#include <QPushButton>
#include <QScatterSeries>
#include <QThread>
#include <QValueAxis>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace palpate {

StiffeningPanel::StiffeningPanel(QWidget* parent) : QWidget(parent) {
    mView = new QChartView(this);
    mView->setObjectName(QStringLiteral("stiffeningChart"));
    mView->setRenderHint(QPainter::Antialiasing);
    mView->chart()->setAnimationOptions(QChart::NoAnimation);
    mView->setMinimumHeight(220);
    mDepthLabel = new QLabel(this);
    mDepthSpin = new QDoubleSpinBox(this);
    mDepthSpin->setObjectName(QStringLiteral("stiffeningDepthSpin"));
    mDepthSpin->setDecimals(1);
    mDepthSpin->setSingleStep(0.5);
    mDepthSpin->setSuffix(QStringLiteral(" mm"));
    mDepthLabel->setBuddy(mDepthSpin);
    mComputeButton = new QPushButton(this);
    mComputeButton->setObjectName(QStringLiteral("computeStiffeningButton"));
    connect(mComputeButton, &QPushButton::clicked, this, [this] { compute(); });
    mApplyButton = new QPushButton(this);
    mApplyButton->setObjectName(QStringLiteral("applyKnotsButton"));
    connect(mApplyButton, &QPushButton::clicked, this, [this] {
        if (mReference && mReference->knots > 0) emit applyKnotsRequested(*mReference);
    });
    mBusy = new QProgressBar(this);
    mBusy->setRange(0, 0);  // a solve reports no fraction: busy while it runs
    mBusy->setVisible(false);
    mBusy->setMaximumHeight(10);
    mBusy->setTextVisible(false);
    mStatusLabel = new QLabel(this);
    mStatusLabel->setObjectName(QStringLiteral("stiffeningStatus"));
    mStatusLabel->setWordWrap(true);
    mStatusLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* row = new QHBoxLayout;
    row->addWidget(mDepthLabel);
    row->addWidget(mDepthSpin);
    row->addWidget(mComputeButton);
    row->addWidget(mApplyButton);
    row->addStretch(1);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(mView, 1);
    layout->addLayout(row);
    layout->addWidget(mBusy);
    layout->addWidget(mStatusLabel);
    setTissue(mContact, mParams);
    retranslateUi();
}

StiffeningPanel::~StiffeningPanel() {
    if (mThread) {
        mThread->wait();  // its queued call to this panel is dropped with the panel
        delete mThread;
    }
}

void StiffeningPanel::setTissue(const ToolContact& contact, const SlopeRingParams& params) {
    const bool sameTissue = sameToolContact(contact, mContact);
    if (!sameTissue || !mReference) {
        mDepthSpin->setRange(0.1 * contact.toolRadiusMm, 1.5 * contact.toolRadiusMm);
        mDepthSpin->setValue(0.6 * contact.toolRadiusMm);
    }
    mContact = contact;
    mParams = params;
    if (!sameTissue && mReference) {
        mReference.reset();
        setStatus(tr("The tissue changed: press Compute for its curve."));
    } else if (mReference) {
        try {
            mReference = knotsFromCurve(mReference->curve, mParams.slopeMagnitudeMmPerN[0]);
        } catch (const std::invalid_argument& e) {
            mReference.reset();
            setStatus(tr("The knots do not fit these slopes: %1").arg(QString::fromUtf8(e.what())), true);
        }
    }
    rebuild();
    updateApplyButton();
}

bool StiffeningPanel::compute() {
    if (mThread) return false;
    StiffeningCalibrationDef def;
    def.material = hyperelasticMaterialOf(mContact);
    def.toolRadiusMm = mContact.toolRadiusMm;
    setStiffeningDepths(def, mDepthSpin->value() / mContact.toolRadiusMm);
    if (const std::string e = joinedMessages(validateStiffeningCalibrationDef(def)); !e.empty()) {
        setStatus(tr("Cannot compute: %1").arg(QString::fromStdString(e)), true);
        return false;
    }
    const double firstSlope = mParams.slopeMagnitudeMmPerN[0];
    mThread = QThread::create([this, def, firstSlope] {
        auto result = std::make_shared<StiffeningCalibration>();
        QString error;
        try {
            const StiffeningCalibration reference = calibrateStiffening(def);
            *result = knotsFromCurve(reference.curve, firstSlope);
            result->completed = reference.completed;
            result->failure = reference.failure;
            result->seconds = reference.seconds;
            result->notes.insert(result->notes.begin(), reference.notes.begin(), reference.notes.end());
        } catch (const std::exception& e) {
            error = QString::fromStdString(e.what());
        }
        // Its last act: the panel joins the thread when it runs this.
        handOffTo(this, [this, result, error] { onFinished(result, error); });
    });
    mThread->setObjectName(QStringLiteral("stiffening reference"));
    mBusy->setVisible(true);
    mComputeButton->setEnabled(false);
    updateApplyButton();
    setStatus(tr("Pressing the hyperelastic half-space to %1 mm…").arg(mDepthSpin->value()));
    mThread->start(QThread::LowPriority);  // the haptic thread and the GUI come first
    return true;
}

void StiffeningPanel::onFinished(const std::shared_ptr<StiffeningCalibration>& result, const QString& error) {
    if (mThread) {
        mThread->wait();
        delete mThread;
        mThread = nullptr;
    }
    mBusy->setVisible(false);
    mComputeButton->setEnabled(true);
    if (!error.isEmpty()) {
        setStatus(tr("The reference could not be computed: %1").arg(error), true);
        emit computed(false);
        return;
    }
    mReference = *result;
    rebuild();
    updateApplyButton();
    emit computed(true);
}

void StiffeningPanel::updateApplyButton() {
    mApplyButton->setEnabled(!mThread && mReference && mReference->completed && mReference->knots > 0);
}

QStringList StiffeningPanel::seriesNames() const {
    QStringList names;
    for (QAbstractSeries* s : mView->chart()->series()) names << s->name();
    return names;
}

QString StiffeningPanel::statusText() const { return mStatusLabel->text(); }

void StiffeningPanel::setStatus(const QString& text, bool problem) {
    mStatusLabel->setText(text);
    mStatusLabel->setStyleSheet(problem ? QStringLiteral("color: #b00020;") : QString());
}

void StiffeningPanel::rebuild() {
    QChart* c = mView->chart();
    c->removeAllSeries();
    for (QAbstractAxis* axis : c->axes()) {
        c->removeAxis(axis);
        delete axis;
    }
    const HyperelasticMaterial law = hyperelasticMaterialOf(mContact);
    // Two short lines, so that a dock's width holds them.
    c->setTitle(QStringLiteral("<b>%1</b><br><span style=\"font-size:small; font-weight:normal\">%2</span>")
                    .arg(tr("Force against depth").toHtmlEscaped(),
                         tr("E = %1 kPa, ν = %2, a = %3 mm, %4 (b = %5)")
                             .arg(mContact.material.youngsModulusNPerMm2 * 1000.0, 0, 'g', 3)
                             .arg(mContact.material.poissonRatio, 0, 'g', 3)
                             .arg(mContact.toolRadiusMm, 0, 'g', 3)
                             .arg(QString::fromLatin1(hyperelasticLawName(law.law).data()))
                             .arg(mContact.stiffeningExponent, 0, 'g', 3)
                             .toHtmlEscaped()));
    if (!mReference || mReference->curve.empty()) {
        c->legend()->setVisible(false);
        if (!mThread && !mStatusLabel->text().contains(QLatin1String("changed")))
            setStatus(tr("Press Compute: the hyperelastic reference is solved for this tissue (a few seconds)."));
        return;
    }
    const auto& curve = mReference->curve;
    const double m1 = mParams.slopeMagnitudeMmPerN[0];
    const double deepest = curve.back().depthMm;
    auto* reference = new QScatterSeries;
    reference->setName(tr("Hyperelastic FEM"));
    reference->setMarkerSize(8.0);
    auto* linear = new QLineSeries;
    linear->setName(tr("Linear model"));
    auto* knots = new QLineSeries;
    // No plural translation is loaded for English: the two forms are spelled out.
    knots->setName(mReference->knots == 1 ? tr("1 knot") : tr("%1 knots").arg(mReference->knots));
    SlopeRingParams calibrated = mParams;
    applyStiffening(*mReference, calibrated);
    QLineSeries* inUse = nullptr;
    if (mParams.stiffeningKnots > 0) {
        inUse = new QLineSeries;
        inUse->setName(mParams.stiffeningKnots == 1 ? tr("the preset's knot")
                                                    : tr("the preset's %1 knots").arg(mParams.stiffeningKnots));
    }
    double forceHi = 0.0;
    for (const StiffeningCurvePoint& p : curve) {
        reference->append(p.depthMm, p.forceN);
        forceHi = std::max(forceHi, p.forceN);
    }
    constexpr int kSamples = 60;
    for (int i = 0; i <= kSamples; ++i) {
        const double d = deepest * i / kSamples;
        linear->append(d, d / m1);
        knots->append(d, knotForceAtDepthN(calibrated, d));
        if (inUse) inUse->append(d, knotForceAtDepthN(mParams, d));
        forceHi = std::max({forceHi, d / m1, knotForceAtDepthN(calibrated, d)});
    }
    auto* x = new QValueAxis;
    x->setTitleText(tr("Depth of the tissue under the tool (mm)"));
    x->setRange(0.0, deepest);
    auto* y = new QValueAxis;
    y->setTitleText(tr("Force (N)"));
    y->setRange(0.0, forceHi * 1.05);
    y->applyNiceNumbers();
    c->addAxis(x, Qt::AlignBottom);
    c->addAxis(y, Qt::AlignLeft);
    for (QAbstractSeries* s : std::initializer_list<QAbstractSeries*>{linear, knots, inUse, reference}) {
        if (!s) continue;
        c->addSeries(s);
        s->attachAxis(x);
        s->attachAxis(y);
    }
    c->legend()->setVisible(true);
    c->legend()->setAlignment(Qt::AlignBottom);
    const double linearError = 1.0 - 1.0 / curve.back().ratio;
    setStatus(tr("At %1 mm the reference is %2 times the linear force: the linear model is %3 % low there, the %4 "
                 "knots are within %5 % everywhere on the curve%6.")
                  .arg(deepest, 0, 'f', 1)
                  .arg(curve.back().ratio, 0, 'f', 3)
                  .arg(100.0 * linearError, 0, 'f', 1)
                  .arg(mReference->knots)
                  .arg(100.0 * mReference->worstKnotErrorFraction, 0, 'f', 1)
                  .arg(mReference->completed ? QString() : tr(" (the solve stopped early: %1)").arg(QString::fromStdString(mReference->failure))));
}

void StiffeningPanel::retranslateUi() {
    mDepthLabel->setText(tr("Press &to:"));
    mDepthSpin->setToolTip(tr("How deep the hyperelastic punch goes (0.1 to 1.5 tool radii)."));
    mComputeButton->setText(tr("&Compute"));
    mApplyButton->setText(tr("&Apply knots"));
    mApplyButton->setToolTip(
        tr("Put these knots into the tissue in use (Parameters: one step to undo) and apply it: "
           "the model stiffens as the reference does. The mesh and the rings stay as they are."));
    mComputeButton->setToolTip(tr("Solve the hyperelastic reference for this tissue (a flat punch of the tool's radius, "
                                  "a few seconds) and fit the stiffening knots to it."));
    rebuild();
}

void StiffeningPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslateUi();
    QWidget::changeEvent(event);
}

}  // namespace palpate
