package robot;

<<handwritten>> component Sensor {
  port <<sync>> out int value;
}
