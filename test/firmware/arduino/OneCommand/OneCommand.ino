// OneCommand - a test sketch for test/cli/cli_pil.sh with the habit of
// the paper's Arduino library: its Motor sends a command only when the value
// changes, so a sketch that sets both motors once and then only reads the
// sensors sends exactly one command. In compat mode the simulator must hold
// it (no silence watchdog, as the paper's Unity simulator) and the robot
// drives on until it is at a wall. Before driving it logs the mean of its
// first 8 front readings at rest, in mm at the compat scale (1.0 m), so the
// test can compare it with the true distance.
// `mmsim --maze MAZE --avr OneCommand.elf --protocol compat`.
#include <Micromouse.h>
#include <stdio.h>

SensorManager sensors(Serial, MM_COMPAT);
ActuatorManager actuators;
Motor leftMotor(MM_LEFT), rightMotor(MM_RIGHT);
DistanceSensor front(MM_TOF_FRONT);

static const uint8_t AT_REST_READINGS = 8; // front readings averaged before the command
static const int16_t DRIVE = 300;          // the one command, of +-1023
static uint8_t seen, count;
static uint32_t sum_mm;
static bool sent;

void setup()
{
    Serial.begin(115200);
    sensors.begin();
    sensors.requestEnableSensors();
}

void loop()
{
    sensors.update();
    if (sent) return; // from now on: only reads, never another command
    uint8_t seq = mmLink.tof_seq[MM_TOF_FRONT];
    if (seq == seen) return;
    seen = seq;
    DistanceReading r = front.getReading();
    if (r.timeout) return;
    sum_mm += r.distance_mm;
    if (++count < AT_REST_READINGS) return;
    char line[48];
    snprintf(line, sizeof line, "OneCommand: front at rest %u mm", (unsigned)(sum_mm / AT_REST_READINGS));
    actuators.log(line);
    leftMotor.setVoltage(DRIVE);
    rightMotor.setVoltage(DRIVE);
    sent = true;
}
