// Bullet's classic "HelloWorld" scene (a static ground box and a falling sphere, stepped 150 times at 60 Hz, the
// positions printed every step), on gq. Compared with stock Bullet only the two construction lines marked "gq"
// differ; everything else is ordinary Bullet API. tests/bullet runs it and checks the sphere comes to rest on the
// ground (y = -5: ground top at -6, radius 1).
#include <cstdio>

#include <btBulletDynamicsCommon.h>

#include "gq/bullet/collision_configuration.h"

int main() {
  // Collision configuration and dispatcher: gq's narrow phase.
  btDefaultCollisionConfiguration* collisionConfiguration = new gq::bullet::CollisionConfiguration();  // gq
  btCollisionDispatcher* dispatcher = new gq::bullet::CollisionDispatcher(collisionConfiguration);      // gq

  btBroadphaseInterface* overlappingPairCache = new btDbvtBroadphase();
  btSequentialImpulseConstraintSolver* solver = new btSequentialImpulseConstraintSolver;
  btDiscreteDynamicsWorld* dynamicsWorld =
      new btDiscreteDynamicsWorld(dispatcher, overlappingPairCache, solver, collisionConfiguration);
  dynamicsWorld->setGravity(btVector3(0, -10, 0));

  // Shapes are kept so they can be deleted at the end.
  btAlignedObjectArray<btCollisionShape*> collisionShapes;

  {  // The ground: a static box of half extent 50, top face at y = -6.
    btCollisionShape* groundShape = new btBoxShape(btVector3(btScalar(50.), btScalar(50.), btScalar(50.)));
    collisionShapes.push_back(groundShape);
    btTransform groundTransform;
    groundTransform.setIdentity();
    groundTransform.setOrigin(btVector3(0, -56, 0));
    btScalar mass(0.);
    btVector3 localInertia(0, 0, 0);
    btDefaultMotionState* myMotionState = new btDefaultMotionState(groundTransform);
    btRigidBody::btRigidBodyConstructionInfo rbInfo(mass, myMotionState, groundShape, localInertia);
    btRigidBody* body = new btRigidBody(rbInfo);
    dynamicsWorld->addRigidBody(body);
  }

  {  // A dynamic sphere of radius 1 and mass 1, released at (2, 10, 0).
    btCollisionShape* colShape = new btSphereShape(btScalar(1.));
    collisionShapes.push_back(colShape);
    btTransform startTransform;
    startTransform.setIdentity();
    btScalar mass(1.f);
    btVector3 localInertia(0, 0, 0);
    colShape->calculateLocalInertia(mass, localInertia);
    startTransform.setOrigin(btVector3(2, 10, 0));
    btDefaultMotionState* myMotionState = new btDefaultMotionState(startTransform);
    btRigidBody::btRigidBodyConstructionInfo rbInfo(mass, myMotionState, colShape, localInertia);
    btRigidBody* body = new btRigidBody(rbInfo);
    dynamicsWorld->addRigidBody(body);
  }

  for (int i = 0; i < 150; i++) {
    dynamicsWorld->stepSimulation(1.f / 60.f, 10);
    for (int j = dynamicsWorld->getNumCollisionObjects() - 1; j >= 0; j--) {
      btCollisionObject* obj = dynamicsWorld->getCollisionObjectArray()[j];
      btRigidBody* body = btRigidBody::upcast(obj);
      btTransform trans;
      if (body && body->getMotionState())
        body->getMotionState()->getWorldTransform(trans);
      else
        trans = obj->getWorldTransform();
      printf("world pos object %d = %f,%f,%f\n", j, float(trans.getOrigin().getX()), float(trans.getOrigin().getY()),
             float(trans.getOrigin().getZ()));
    }
  }

  // Cleanup in the reverse order of creation.
  for (int i = dynamicsWorld->getNumCollisionObjects() - 1; i >= 0; i--) {
    btCollisionObject* obj = dynamicsWorld->getCollisionObjectArray()[i];
    btRigidBody* body = btRigidBody::upcast(obj);
    if (body && body->getMotionState()) delete body->getMotionState();
    dynamicsWorld->removeCollisionObject(obj);
    delete obj;
  }
  for (int j = 0; j < collisionShapes.size(); j++) {
    btCollisionShape* shape = collisionShapes[j];
    collisionShapes[j] = 0;
    delete shape;
  }
  delete dynamicsWorld;
  delete solver;
  delete overlappingPairCache;
  delete dispatcher;
  delete collisionConfiguration;
  collisionShapes.clear();
  return 0;
}
