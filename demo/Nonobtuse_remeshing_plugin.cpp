// SPDX-License-Identifier: GPL-3.0-or-later
//
// Polyhedron demo plugin of the Nonobtuse_remeshing package: the submenu
// "Polygon Mesh Processing/Nonobtuse Remeshing" with three actions on a
// selected surface mesh item,
//   - "Nonobtuse remesh...": nonobtuse_remesh() into a new item,
//   - "Angle-bounded decimation...": angle_bounded_decimation() of a certified
//     item into a new item,
//   - "Certify angle bounds": certify_angle_bounds(), offending faces in red.
// Long runs show a QProgressDialog whose Cancel button reaches the library
// through its visitors (keep_going() returns false); the library then returns
// a mesh that is still certified.
//
// For scripts (the demo's QtScript engine sees every plugin as a global object
// named after its library file, here `nonobtuse_remeshing_plugin`), the
// actions have dialog-free slots: remesh(), remeshToVertices(), decimate(),
// certify(), saveSelected() and quitAfter(). They report through the demo's
// message console and standard output, never through a modal box.
//
// Only the package's public entry points are used.

#include <CGAL/Three/Polyhedron_demo_plugin_interface.h>
#include <CGAL/Three/Scene_group_item.h>
#include <CGAL/Three/Scene_interface.h>
#include <CGAL/Three/Three.h>

#include "Messages_interface.h"
#include "Scene_surface_mesh_item.h"

#include <CGAL/nonobtuse_remeshing.h>
#include <CGAL/Nonobtuse_remeshing/nonobtuse_remesh.h>

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFormLayout>
#include <QLabel>
#include <QMainWindow>
#include <QMessageBox>
#include <QPointer>
#include <QProgressDialog>
#include <QSpinBox>
#include <QStackedWidget>
#include <QString>
#include <QTimer>
#include <QVBoxLayout>
#include <QtPlugin>

#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <iostream>
#include <memory>
#include <string>

namespace NR = CGAL::Nonobtuse_remeshing;

namespace {

QString stage_label(NR::Remeshing_stage stage)
{
  return QString::fromLatin1(NR::stage_description(stage));
}

// Share of the progress bar of each stage: [begin, end) out of 1000.
void stage_span(NR::Remeshing_stage stage, int& begin, int& end)
{
  switch(stage) {
  case NR::Remeshing_stage::initial_mesh: begin = 0; end = 100; return;
  case NR::Remeshing_stage::valence: begin = 100; end = 200; return;
  case NR::Remeshing_stage::fit: begin = 200; end = 800; return;
  case NR::Remeshing_stage::decimation: begin = 800; end = 1000; return;  // only over the target
  }
  begin = 0; end = 1000;
}

// Updates a progress dialog and answers its Cancel button, at most every
// 50 ms (the library calls keep_going() often).
class Progress_reporter
{
public:
  Progress_reporter(QWidget* parent, const QString& title)
  {
    dialog_ = new QProgressDialog(title, QObject::tr("Cancel"), 0, 1000, parent);
    dialog_->setWindowTitle(title);
    dialog_->setWindowModality(Qt::WindowModal);
    dialog_->setMinimumDuration(300);
    dialog_->setAutoClose(false);
    dialog_->setAutoReset(false);
    dialog_->setValue(0);
    timer_.start();
  }
  ~Progress_reporter() { delete dialog_; }
  Progress_reporter(const Progress_reporter&) = delete;
  Progress_reporter& operator=(const Progress_reporter&) = delete;

  // Shows `value` out of 1000, or a busy bar when `value` is negative;
  // returns false once the user has cancelled.
  bool update(int value, const QString& label, bool force = false)
  {
    if(dialog_.isNull()) return true;
    if(force || timer_.elapsed() >= 50) {
      timer_.restart();
      dialog_->setLabelText(label);
      if(value < 0) {
        dialog_->setRange(0, 0);
        dialog_->setValue(0);
      } else {
        if(dialog_->maximum() == 0) dialog_->setRange(0, 1000);
        dialog_->setValue((std::min)(1000, value));
      }
      QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    }
    return !dialog_->wasCanceled();
  }
  bool cancelled() const { return !dialog_.isNull() && dialog_->wasCanceled(); }

private:
  QPointer<QProgressDialog> dialog_;
  QElapsedTimer timer_;
};

// The visitor of nonobtuse_remesh().
struct Remeshing_visitor
{
  Progress_reporter* progress;
  NR::Remeshing_stage stage = NR::Remeshing_stage::initial_mesh;

  void stage_started(NR::Remeshing_stage s)
  {
    stage = s;
    int begin, end;
    stage_span(s, begin, end);
    progress->update(begin, QObject::tr("Nonobtuse remeshing: %1...").arg(stage_label(s)), true);
    std::cout << "nonobtuse_remeshing: stage " << stage_label(s).toStdString() << std::endl;
  }
  void stage_finished(NR::Remeshing_stage s, double seconds)
  {
    std::cout << "nonobtuse_remeshing: stage " << stage_label(s).toStdString() << " done in " << seconds
              << " s" << std::endl;
  }
  bool keep_going(const NR::Remeshing_progress& p)
  {
    int begin, end;
    stage_span(p.stage, begin, end);
    // The fit cannot tell how far it is: a busy bar then; the decimation
    // counts its collapses towards the target.
    int value = p.fraction >= 0. ? begin + int(std::lround(p.fraction * double(end - begin))) : -1;
    if(p.decimation != nullptr) {
      const NR::Angle_bounded_decimation_statistics& s = *p.decimation;
      const double todo = s.vertices_before > s.target_vertices ? double(s.vertices_before - s.target_vertices) : 1.;
      value = begin + int(std::lround((std::min)(1., double(s.collapses) / todo) * double(end - begin)));
    }
    QString label = QObject::tr("Nonobtuse remeshing: %1").arg(stage_label(p.stage));
    if(p.fit != nullptr)
      label += QObject::tr("\n%1: %2 moves, RMS distance %3 % of the diagonal")
                   .arg(p.fit->stage == NR::Deform_to_fit_stage::smoothing ? QObject::tr("smoothing")
                                                                           : QObject::tr("optimization"))
                   .arg(qulonglong(p.fit->moves))
                   .arg(p.fit->rms_distance, 0, 'g', 3);
    return progress->update(value, label);
  }
};

// The visitor of angle_bounded_decimation().
struct Decimation_visitor
{
  Progress_reporter* progress;
  bool keep_going(const NR::Angle_bounded_decimation_statistics& s)
  {
    const double todo = s.vertices_before > s.target_vertices ? double(s.vertices_before - s.target_vertices) : 1.;
    const double done = (std::min)(1., double(s.collapses) / todo);
    return progress->update(int(std::lround(1000. * done)),
                            QObject::tr("Angle-bounded decimation: %1 collapses, %2 rounds")
                                .arg(qulonglong(s.collapses))
                                .arg(qulonglong(s.rounds)));
  }
};

QString certificate_summary(const NR::Angle_certificate<face_descriptor>& c)
{
  QString text;
  if(c.is_certified())
    text = QObject::tr("certified: all %1 faces have their angles in [%2°, %3°]")
               .arg(qulonglong(c.faces)).arg(c.min_bound).arg(c.max_bound);
  else
    text = QObject::tr("NOT certified in [%1°, %2°]: %3 offending faces out of %4 (%5 corners below, %6 above, "
                       "%7 degenerate faces)")
               .arg(c.min_bound).arg(c.max_bound)
               .arg(qulonglong(c.offending_faces.size())).arg(qulonglong(c.faces))
               .arg(qulonglong(c.too_small_corners)).arg(qulonglong(c.too_large_corners))
               .arg(qulonglong(c.degenerate_faces));
  if(c.has_angles())
    text += QObject::tr("; angles from %1° to %2°").arg(c.min_angle, 0, 'f', 3).arg(c.max_angle, 0, 'f', 3);
  return text;
}

} // namespace

using namespace CGAL::Three;

class Polyhedron_demo_nonobtuse_remeshing_plugin : public QObject, public Polyhedron_demo_plugin_interface
{
  Q_OBJECT
  Q_INTERFACES(CGAL::Three::Polyhedron_demo_plugin_interface)
  Q_PLUGIN_METADATA(IID "com.geometryfactory.PolyhedronDemo.PluginInterface/1.0" FILE "nonobtuse_remeshing_plugin.json")

public:
  void init(QMainWindow* main_window, Scene_interface* scene_interface, Messages_interface* messages) override
  {
    mw = main_window;
    scene = scene_interface;
    this->messages = messages;
    const QString menu = QStringLiteral("Polygon Mesh Processing/Nonobtuse Remeshing");

    action_remesh = new QAction(tr("Nonobtuse remesh..."), mw);
    action_remesh->setObjectName("actionNonobtuseRemesh");
    action_remesh->setProperty("subMenuName", menu);
    connect(action_remesh, SIGNAL(triggered()), this, SLOT(on_remesh_triggered()));

    action_decimate = new QAction(tr("Angle-bounded decimation..."), mw);
    action_decimate->setObjectName("actionAngleBoundedDecimation");
    action_decimate->setProperty("subMenuName", menu);
    connect(action_decimate, SIGNAL(triggered()), this, SLOT(on_decimate_triggered()));

    action_certify = new QAction(tr("Certify angle bounds"), mw);
    action_certify->setObjectName("actionCertifyAngleBounds");
    action_certify->setProperty("subMenuName", menu);
    connect(action_certify, SIGNAL(triggered()), this, SLOT(certify()));
  }

  QList<QAction*> actions() const override
  {
    return QList<QAction*>() << action_remesh << action_decimate << action_certify;
  }

  bool applicable(QAction*) const override { return selected_item() != nullptr; }

public Q_SLOTS:
  // Interactive actions: a dialog, then the run.
  void on_remesh_triggered();
  void on_decimate_triggered();

  // Scriptable, dialog-free entry points. Each works on the selected item,
  // reports to the console and standard output, and returns false (or -1) on
  // failure. The new item, if any, becomes the selected one.

  /// nonobtuse_remesh() with `resolution` cubes along the longest side.
  bool remesh(int resolution, double alpha, int smoothing_steps)
  {
    return run_remesh({resolution, 0, 0.}, alpha, smoothing_steps, true, false);
  }
  /// nonobtuse_remesh() with the resolution chosen for about `target_vertices`.
  bool remeshToVertices(int target_vertices, double alpha, int smoothing_steps)
  {
    return run_remesh({0, target_vertices, 0.}, alpha, smoothing_steps, true, false);
  }
  /// nonobtuse_remesh() with the fewest vertices within `max_distance_percent`
  /// of the diagonal (symmetric Hausdorff distance, measured); false also
  /// when the bound is not met (the closest mesh found is added).
  bool remeshToDistance(double max_distance_percent, double alpha, int smoothing_steps)
  {
    return run_remesh({0, 0, max_distance_percent}, alpha, smoothing_steps, true, false);
  }
  /// angle_bounded_decimation() to `ratio` of the vertices; `max_error_percent`
  /// of the diagonal stops it earlier (0: no such limit).
  bool decimate(double ratio, double max_error_percent) { return run_decimation(ratio, max_error_percent, false); }
  /// certify_angle_bounds(): colours the offending faces red; returns their
  /// number, or -1 when no surface mesh is selected or it cannot be certified.
  int certify();
  /// Writes the selected item with the package's full-precision writer, if
  /// the written file certifies in [30, 90] degrees.
  bool saveSelected(const QString& filename);
  /// Closes the main window `msec` milliseconds after the event loop runs.
  void quitAfter(int msec)
  {
    QTimer::singleShot(msec, mw, [this]() { mw->close(); });
  }

private:
  Scene_surface_mesh_item* selected_item() const
  {
    return qobject_cast<Scene_surface_mesh_item*>(scene->item(scene->mainSelectionIndex()));
  }
  void report(const QString& text, bool warning = false)
  {
    std::cout << "nonobtuse_remeshing: " << text.toStdString() << std::endl;
    if(messages) {
      if(warning) messages->message_warning(text);
      else messages->message_information(text);
    }
  }
  void report_error(const QString& text, bool interactive)
  {
    std::cerr << "nonobtuse_remeshing: error: " << text.toStdString() << std::endl;
    if(messages) messages->message_error(text);
    if(interactive) QMessageBox::warning(mw, tr("Nonobtuse remeshing"), text);
  }
  // A non-modal box: never blocks a script or the event loop.
  void show_summary(const QString& title, const QString& text)
  {
    QMessageBox* box = new QMessageBox(QMessageBox::Information, title, text, QMessageBox::Ok, mw);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setModal(false);
    box->show();
  }
  Scene_interface::Item_id add_result(Scene_surface_mesh_item* input, SMesh&& mesh, const QString& name,
                                      bool hide_input)
  {
    mesh.collect_garbage();
    Scene_surface_mesh_item* item = new Scene_surface_mesh_item(std::move(mesh));
    item->setName(name);
    item->setColor(QColor(110, 170, 230));
    item->setRenderingMode(FlatPlusEdges);
    const Scene_interface::Item_id id = scene->addItem(item);
    if(input != nullptr) {
      // next to the input: in its group, if it has one
      if(input->parentGroup() != nullptr) scene->changeGroup(item, input->parentGroup());
      if(hide_input) input->setVisible(false);
    }
    scene->setSelectedItem(id);
    return id;
  }
  // What sizes the remeshed mesh: one of the three is set.
  struct Size
  {
    int resolution;
    int target_vertices;
    double max_distance_percent;
  };
  bool run_remesh(const Size& size, double alpha, int smoothing_steps, bool hide_input, bool interactive);
  bool run_decimation(double ratio, double max_error_percent, bool interactive);

  QMainWindow* mw = nullptr;
  Scene_interface* scene = nullptr;
  Messages_interface* messages = nullptr;
  QAction* action_remesh = nullptr;
  QAction* action_decimate = nullptr;
  QAction* action_certify = nullptr;
  // dialog values, kept between runs
  int last_mode = 0, last_resolution = 60, last_target_vertices = 5000, last_smoothing = 2;
  double last_max_distance = 1., last_alpha = 0.5, last_ratio = 0.5, last_max_error = 0.;
  bool last_hide_input = true;
};

void Polyhedron_demo_nonobtuse_remeshing_plugin::on_remesh_triggered()
{
  Scene_surface_mesh_item* item = selected_item();
  if(!item) return;

  QDialog dialog(mw);
  dialog.setWindowTitle(tr("Nonobtuse remeshing of %1").arg(item->name()));
  QVBoxLayout* layout = new QVBoxLayout(&dialog);
  QLabel* intro = new QLabel(tr("Remeshes into a mesh whose angles all lie in [30°, 90°], certified exactly.\n"
                                "Input: %1 vertices, %2 faces.")
                                 .arg(qulonglong(num_vertices(*item->face_graph())))
                                 .arg(qulonglong(num_faces(*item->face_graph()))));
  layout->addWidget(intro);
  QFormLayout* form = new QFormLayout;
  layout->addLayout(form);

  QComboBox* mode = new QComboBox;
  mode->addItem(tr("Resolution (cubes along the longest side)"));
  mode->addItem(tr("Target vertex count"));
  mode->addItem(tr("Distance bound (% of the diagonal)"));
  mode->setCurrentIndex(last_mode);
  form->addRow(tr("Size by"), mode);

  QStackedWidget* size = new QStackedWidget;
  QSpinBox* resolution = new QSpinBox;
  resolution->setRange(1, 1024);
  resolution->setValue(last_resolution);
  resolution->setToolTip(tr("Grid of N cubes along the longest side of the bounding box"));
  QSpinBox* target = new QSpinBox;
  target->setRange(10, 10000000);
  target->setValue(last_target_vertices);
  target->setToolTip(tr("The resolution is chosen so that the result has about this many vertices"));
  QDoubleSpinBox* distance = new QDoubleSpinBox;
  distance->setRange(0.01, 10.);
  distance->setDecimals(3);
  distance->setSingleStep(0.1);
  distance->setValue(last_max_distance);
  distance->setToolTip(tr("The fewest vertices whose symmetric Hausdorff distance to the input, measured on the "
                          "result, is at most this % of the input's bounding-box diagonal"));
  size->addWidget(resolution);
  size->addWidget(target);
  size->addWidget(distance);
  size->setCurrentIndex(last_mode);
  connect(mode, SIGNAL(currentIndexChanged(int)), size, SLOT(setCurrentIndex(int)));
  form->addRow(tr("Size"), size);

  QDoubleSpinBox* alpha = new QDoubleSpinBox;
  alpha->setRange(0., 1.);
  alpha->setDecimals(3);
  alpha->setSingleStep(0.05);
  alpha->setValue(last_alpha);
  alpha->setToolTip(tr("Weight of the distance term against the smoothness term in deform-to-fit"));
  form->addRow(tr("Alpha (fit vs smoothness)"), alpha);

  QSpinBox* smoothing = new QSpinBox;
  smoothing->setRange(0, 100);
  smoothing->setValue(last_smoothing);
  smoothing->setToolTip(tr("Constrained Laplacian smoothing passes between optimizations"));
  form->addRow(tr("Smoothing steps"), smoothing);

  QCheckBox* hide = new QCheckBox(tr("Hide the input"));
  hide->setChecked(last_hide_input);
  form->addRow(QString(), hide);

  QDialogButtonBox* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  connect(buttons, SIGNAL(accepted()), &dialog, SLOT(accept()));
  connect(buttons, SIGNAL(rejected()), &dialog, SLOT(reject()));
  layout->addWidget(buttons);

  if(dialog.exec() != QDialog::Accepted) return;
  last_mode = mode->currentIndex();
  last_resolution = resolution->value();
  last_target_vertices = target->value();
  last_max_distance = distance->value();
  last_alpha = alpha->value();
  last_smoothing = smoothing->value();
  last_hide_input = hide->isChecked();
  run_remesh({last_mode == 0 ? last_resolution : 0, last_mode == 1 ? last_target_vertices : 0,
              last_mode == 2 ? last_max_distance : 0.},
             last_alpha, last_smoothing, last_hide_input, true);
}

bool Polyhedron_demo_nonobtuse_remeshing_plugin::run_remesh(const Size& size, double alpha, int smoothing_steps,
                                                             bool hide_input, bool interactive)
{
  Scene_surface_mesh_item* item = selected_item();
  if(!item) {
    report_error(tr("Nonobtuse remesh: select a surface mesh item first"), interactive);
    return false;
  }
  // the run processes events: the item may be gone when it ends
  const Scene_interface::Item_id input_id = scene->item_id(item);
  const QString input_name = item->name();
  SMesh input;
  CGAL::copy_face_graph(*item->face_graph(), input);  // no garbage, no display properties
  SMesh output;
  NR::Nonobtuse_remeshing_statistics stats;
  {
    Progress_reporter progress(mw, tr("Nonobtuse remeshing"));
    Remeshing_visitor visitor{&progress};
    try {
      const auto common = NR::parameters::combine(NR::parameters::alpha(alpha),
                                                  NR::parameters::smoothing_steps(smoothing_steps),
                                                  NR::parameters::remeshing_visitor(std::ref(visitor)));
      if(size.max_distance_percent > 0.)
        stats = NR::nonobtuse_remesh(
            input, output,
            NR::parameters::combine(NR::parameters::max_distance(size.max_distance_percent / 100.), common));
      else if(size.target_vertices > 0)
        stats = NR::nonobtuse_remesh(
            input, output,
            NR::parameters::combine(NR::parameters::target_vertices(std::size_t(size.target_vertices)), common));
      else
        stats = NR::nonobtuse_remesh(input, output,
                                     NR::parameters::combine(NR::parameters::resolution(size.resolution), common));
    } catch(const std::exception& e) {
      report_error(tr("Nonobtuse remesh of %1 failed: %2").arg(input_name).arg(QString::fromUtf8(e.what())),
                   interactive);
      return false;
    }
  }
  if(num_faces(output) == 0) {
    report(tr("Nonobtuse remesh of %1: %2, no mesh to add")
               .arg(input_name)
               .arg(stats.cancelled ? tr("cancelled") : tr("the result is empty (resolution too small?)")),
           true);
    return false;
  }
  // The library certifies its output; the plugin says so on what it adds.
  const auto certificate = NR::certify_angle_bounds(output);
  // with a bound: the distance the library measured on the output
  const NR::Distance_bound_statistics& bound = stats.distance;
  const bool bounded = size.max_distance_percent > 0.;
  const QString refined_for = stats.refinements > 0 && bound.refinements > 0 ? tr("the input's topology and the bound")
                              : stats.refinements > 0                        ? tr("the input's topology")
                                                                             : tr("the distance bound");
  const QString distance =
      bounded ? tr("; Hausdorff distance %1% of the diagonal, %2 the bound %3% (measured within %4%)")
                    .arg(100. * bound.distance, 0, 'f', 3)
                    .arg(bound.met ? tr("within") : tr("over"))
                    .arg(size.max_distance_percent)
                    .arg(100. * bound.measurement_error, 0, 'f', 3)
              : QString();
  const QString summary =
      tr("Nonobtuse remesh of %1 (resolution %2, alpha %3, smoothing %4)%5: %6 vertices, %7 faces in %8 s; %9%10")
          .arg(input_name)
          .arg(stats.resolution == stats.budget_resolution
                   ? QString::number(stats.resolution)
                   : tr("%1, refined from %2 for %3").arg(stats.resolution).arg(stats.budget_resolution).arg(refined_for))
          .arg(alpha)
          .arg(smoothing_steps)
          .arg(stats.cancelled ? tr(", cancelled") : QString())
          .arg(qulonglong(num_vertices(output)))
          .arg(qulonglong(num_faces(output)))
          .arg(stats.seconds, 0, 'f', 2)
          .arg(certificate_summary(certificate))
          .arg(distance);
  const QString name = bounded ? tr("%1 (nonobtuse, %2%)").arg(input_name).arg(size.max_distance_percent)
                               : tr("%1 (nonobtuse, N=%2)").arg(input_name).arg(stats.resolution);
  add_result(scene->item(input_id) == item ? item : nullptr, std::move(output), name, hide_input);
  const bool ok = certificate.is_certified() && (!bounded || bound.met);
  report(summary, !ok);
  if(interactive) show_summary(tr("Nonobtuse remeshing"), summary);
  return ok;
}

void Polyhedron_demo_nonobtuse_remeshing_plugin::on_decimate_triggered()
{
  Scene_surface_mesh_item* item = selected_item();
  if(!item) return;

  QDialog dialog(mw);
  dialog.setWindowTitle(tr("Angle-bounded decimation of %1").arg(item->name()));
  QVBoxLayout* layout = new QVBoxLayout(&dialog);
  layout->addWidget(new QLabel(tr("Edge collapses that keep every angle in [30°, 90°].\n"
                                  "The item must certify in [30°, 90°]. Input: %1 vertices.")
                                   .arg(qulonglong(num_vertices(*item->face_graph())))));
  QFormLayout* form = new QFormLayout;
  layout->addLayout(form);
  QDoubleSpinBox* ratio = new QDoubleSpinBox;
  ratio->setRange(0.001, 1.);
  ratio->setDecimals(3);
  ratio->setSingleStep(0.05);
  ratio->setValue(last_ratio);
  ratio->setToolTip(tr("Fraction of the vertices to keep"));
  form->addRow(tr("Vertex ratio"), ratio);
  QDoubleSpinBox* max_error = new QDoubleSpinBox;
  max_error->setRange(0., 100.);
  max_error->setDecimals(4);
  max_error->setSingleStep(0.1);
  max_error->setSuffix(tr(" % of diagonal"));
  max_error->setSpecialValueText(tr("none"));
  max_error->setValue(last_max_error);
  max_error->setToolTip(tr("Stop when the cheapest collapse would move farther than this (0: no limit)"));
  form->addRow(tr("Maximum error"), max_error);
  QDialogButtonBox* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  connect(buttons, SIGNAL(accepted()), &dialog, SLOT(accept()));
  connect(buttons, SIGNAL(rejected()), &dialog, SLOT(reject()));
  layout->addWidget(buttons);
  if(dialog.exec() != QDialog::Accepted) return;
  last_ratio = ratio->value();
  last_max_error = max_error->value();
  run_decimation(last_ratio, last_max_error, true);
}

bool Polyhedron_demo_nonobtuse_remeshing_plugin::run_decimation(double ratio, double max_error_percent,
                                                                 bool interactive)
{
  Scene_surface_mesh_item* item = selected_item();
  if(!item) {
    report_error(tr("Angle-bounded decimation: select a surface mesh item first"), interactive);
    return false;
  }
  // the run processes events: the item may be gone when it ends
  const Scene_interface::Item_id input_id = scene->item_id(item);
  const QString input_name = item->name();
  SMesh mesh;
  CGAL::copy_face_graph(*item->face_graph(), mesh);
  try {
    const auto certificate = NR::certify_angle_bounds(mesh);
    if(!certificate.is_certified()) {
      report_error(tr("Angle-bounded decimation needs an item certified in [30°, 90°]; %1 is %2. "
                      "Remesh it first (Nonobtuse remesh...).")
                       .arg(item->name())
                       .arg(certificate_summary(certificate)),
                   interactive);
      return false;
    }
  } catch(const std::exception& e) {
    report_error(tr("Angle-bounded decimation of %1: %2").arg(item->name()).arg(QString::fromUtf8(e.what())),
                 interactive);
    return false;
  }
  const std::size_t before = num_vertices(mesh);
  NR::Angle_bounded_decimation_statistics stats;
  {
    Progress_reporter progress(mw, tr("Angle-bounded decimation"));
    Decimation_visitor visitor{&progress};
    try {
      const auto common = NR::parameters::combine(NR::parameters::vertex_ratio(ratio),
                                                  NR::parameters::decimation_visitor(std::ref(visitor)));
      if(max_error_percent > 0.)
        stats = NR::angle_bounded_decimation(
            mesh, NR::parameters::combine(NR::parameters::max_error(max_error_percent / 100.), common));
      else
        stats = NR::angle_bounded_decimation(mesh, common);
    } catch(const std::exception& e) {
      report_error(tr("Angle-bounded decimation of %1 failed: %2").arg(input_name).arg(QString::fromUtf8(e.what())),
                   interactive);
      return false;
    }
  }
  mesh.collect_garbage();
  const auto certificate = NR::certify_angle_bounds(mesh);
  const QString summary = tr("Angle-bounded decimation of %1 (ratio %2, max error %3): %4 -> %5 vertices, "
                             "%6 collapses in %7 s (%8); %9")
                              .arg(input_name)
                              .arg(ratio)
                              .arg(max_error_percent > 0. ? tr("%1 %").arg(max_error_percent) : tr("none"))
                              .arg(qulonglong(before))
                              .arg(qulonglong(num_vertices(mesh)))
                              .arg(qulonglong(stats.collapses))
                              .arg(stats.seconds, 0, 'f', 2)
                              .arg(QString::fromLatin1(NR::stop_reason_name(stats.stop_reason)))
                              .arg(certificate_summary(certificate));
  const QString name = tr("%1 (decimated %2)").arg(input_name).arg(ratio);
  add_result(scene->item(input_id) == item ? item : nullptr, std::move(mesh), name, true);
  report(summary, !certificate.is_certified());
  if(interactive) show_summary(tr("Angle-bounded decimation"), summary);
  return certificate.is_certified();
}

int Polyhedron_demo_nonobtuse_remeshing_plugin::certify()
{
  Scene_surface_mesh_item* item = selected_item();
  if(!item) {
    report_error(tr("Certify angle bounds: select a surface mesh item first"), false);
    return -1;
  }
  SMesh& mesh = *item->face_graph();
  NR::Angle_certificate<face_descriptor> certificate;
  try {
    certificate = NR::certify_angle_bounds(mesh);
  } catch(const std::exception& e) {
    report_error(tr("Certify angle bounds of %1: %2").arg(item->name()).arg(QString::fromUtf8(e.what())), false);
    return -1;
  }

  const bool coloured = item->property("nonobtuse_offending_coloured").toBool();
  if(!certificate.offending_faces.empty()) {
    // Patch 0: faces within the bounds, in the item's colour; patch 1: the
    // offending faces, in red (the colour vector is indexed from the smallest
    // patch id present).
    item->setItemIsMulticolor(true);
    auto patch = mesh.property_map<face_descriptor, int>("f:patch_id").first;
    for(face_descriptor f : faces(mesh)) put(patch, f, 0);
    for(face_descriptor f : certificate.offending_faces) put(patch, f, 1);
    const QColor bad(230, 30, 30);
    std::vector<QColor>& colours = item->color_vector();
    colours.clear();
    if(certificate.offending_faces.size() < num_faces(mesh)) colours.push_back(item->color());
    colours.push_back(bad);
    colours.push_back(bad);
    item->computeItemColorVectorAutomatically(false);
    item->setProperty("nonobtuse_offending_coloured", true);
    item->invalidateOpenGLBuffers();
    scene->itemChanged(item);
  } else if(coloured) {
    item->setItemIsMulticolor(false);
    item->setProperty("nonobtuse_offending_coloured", false);
    item->invalidateOpenGLBuffers();
    scene->itemChanged(item);
  }
  const QString summary = tr("%1: %2").arg(item->name()).arg(certificate_summary(certificate));
  report(summary + (certificate.offending_faces.empty() ? QString() : tr(" (offending faces in red)")),
         !certificate.is_certified());
  return int(certificate.offending_faces.size());
}

bool Polyhedron_demo_nonobtuse_remeshing_plugin::saveSelected(const QString& filename)
{
  Scene_surface_mesh_item* item = selected_item();
  if(!item) {
    report_error(tr("Save: select a surface mesh item first"), false);
    return false;
  }
  SMesh mesh;
  CGAL::copy_face_graph(*item->face_graph(), mesh);
  try {
    // the file is re-read and certified before it replaces anything
    NR::write_mesh_atomically(filename.toStdString(), mesh, NR::certifying_check(mesh));
  } catch(const std::exception& e) {
    report_error(tr("Save of %1 failed: %2").arg(item->name()).arg(QString::fromUtf8(e.what())), false);
    return false;
  }
  report(tr("%1 written to %2 (full precision, certified in [30, 90] on the written file)")
             .arg(item->name())
             .arg(filename));
  return true;
}

#include "Nonobtuse_remeshing_plugin.moc"
