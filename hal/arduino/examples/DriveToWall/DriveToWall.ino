// DriveToWall - the smallest useful sketch with the paper's API: enable the
// sensors, drive forward, stop when the front sensor sees a wall nearer than
// 100 mm and log the encoder counts driven. Compat protocol at 115200 baud,
// as the paper's Unity simulator:
// `mmsim --maze MAZE --serial /dev/ttyACM0 --protocol compat`.
#include <Micromouse.h>
#include <stdio.h>

SensorManager sensors(Serial, MM_COMPAT);
ActuatorManager actuators;
Motor leftMotor(MM_LEFT), rightMotor(MM_RIGHT);
Encoder leftEncoder(MM_LEFT), rightEncoder(MM_RIGHT);
DistanceSensor front(MM_TOF_FRONT);

static unsigned long next_us;
static bool stopped;

void setup()
{
    Serial.begin(115200);
    sensors.begin();
    sensors.requestEnableSensors();
    actuators.log("DriveToWall: go");
    next_us = micros();
}

void loop()
{
    sensors.update();
    if ((long)(micros() - next_us) < 0) return;
    next_us += 5000; // a command every 5 ms (6 bytes = 0.5 ms of the link at 115200)
    DistanceReading r = front.getReading();
    bool wall = !r.timeout && r.distance_mm < 100;
    if (wall && !stopped) {
        stopped = true;
        char line[48];
        snprintf(line, sizeof line, "DriveToWall: wall, counts %ld %ld", (long)leftEncoder.getCounts(),
                 (long)rightEncoder.getCounts());
        actuators.log(line);
    }
    int16_t v = stopped ? 0 : 300;
    leftMotor.setVoltage(v);
    rightMotor.setVoltage(v);
}
