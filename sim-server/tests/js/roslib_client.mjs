// A real roslib 2.x client (ESM, named exports) against maa-sim's rosbridge endpoint.
// Usage: node roslib_client.mjs "ws://127.0.0.1:PORT/?token=TOKEN" ; prints one JSON line with what it saw.
// A browser cannot set an Authorization header on a WebSocket, so the token is in the URL.
import { Ros, Topic, Service } from 'roslib';

const url = process.argv[2];
const timeout = setTimeout(() => {
  console.error('roslib client: timed out');
  process.exit(2);
}, 30000);

function once(topic) {
  return new Promise((resolve) => {
    const handler = (message) => {
      topic.unsubscribe(handler);
      resolve(message);
    };
    topic.subscribe(handler);
  });
}

const ros = new Ros({ url });
await new Promise((resolve, reject) => {
  ros.on('connection', resolve);
  ros.on('error', reject);
});

const topics = await new Promise((resolve, reject) => ros.getTopics(resolve, reject));
const topicType = await new Promise((resolve, reject) => ros.getTopicType('/joint_states', resolve, reject));

// Subscribe first, then resume the (paused) simulation through its control service.
const distanceTopic = new Topic({ ros, name: '/sensors/distance', messageType: 'std_msgs/msg/Int32', throttle_rate: 50, queue_length: 1 });
const distancePromise = once(distanceTopic);
const armPromise = new Promise((resolve) => {
  const topic = new Topic({ ros, name: '/toast/ctrl/arm', messageType: 'std_msgs/msg/String' });
  const handler = (message) => {
    if (message.data === 'FETCH') {
      topic.unsubscribe(handler);
      resolve(message.data);
    }
  };
  topic.subscribe(handler);
});
await new Promise((resolve) => setTimeout(resolve, 200));
const resumed = await new Promise((resolve, reject) => {
  new Service({ ros, name: '/sim/resume', serviceType: 'maa_sim/Control' }).callService({}, resolve, reject);
});
console.error(`resumed: ${JSON.stringify(resumed.status?.paused)}`);
const distance = await distancePromise;
console.error(`distance: ${distance.data}`);
const armCommand = await armPromise;
console.error(`arm: ${armCommand}`);

const chatter = new Topic({ ros, name: '/roslib/chatter', messageType: 'std_msgs/msg/String' });
const echoed = once(chatter);
await new Promise((resolve) => setTimeout(resolve, 100));
chatter.publish({ data: 'hello from roslib' });
const echo = await echoed;

const serviceError = await new Promise((resolve) => {
  const step = new Service({ ros, name: '/sim/set_speed', serviceType: 'maa_sim/SetSpeed' });
  step.callService({ speed: 'fast' }, () => resolve(''), (error) => resolve(String(error)));
});

console.log(JSON.stringify({ topics: topics.topics, topicType, distance: distance.data, armCommand, echo: echo.data, serviceError }));
clearTimeout(timeout);
ros.close();
process.exit(0);
