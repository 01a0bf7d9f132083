:- module(oro_events_delivery,
          [ subscriber/4,               % ?Subscriber, ?Queue, ?Thread, ?Owner
            subscriber_create/4,        % :Deliver, -Subscriber, +Options, +Owner
            subscriber_registry/2,      % +Subscriber, -Registry
            claim_subscriber/3,         % +Subscriber, -Queue, -Thread
            claim_callback_subscribers/1, % -Stops
            callback_subscribers/2,     % +Id, -Subscribers
            stop_delivery/4,            % +Name, +Queue, +Thread, +How
            note_callback/2,            % +Id, +Subscriber
            firings/6,                  % +Type, +Trigger, +State0, +Outcome, -Contents, -Remove
            fire/2,                     % +Id, +Content
            run_direct_deliveries/0
          ]).
:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(option)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/events/oro_events_registry)).

/** <module> Events: subscribers and the delivery of firings

What a watcher sends when its state changes (firings/6), and how it
reaches its subscribers: each subscriber owns a bounded queue and a
delivery thread calling its Deliver goal (or, for an in_watcher
subscriber, a call by the watcher thread once the change is over), so
that a slow subscriber never blocks writers, the watcher thread or
other subscribers; a subscriber whose queue is full is dropped
(overflow/1).  This module owns the table of live subscribers
(subscriber/4, callback_subscriber/2, discarding/1, pending_direct/3),
guarded by the mutex `oro_events_delivery`; the public predicates that
create and destroy subscribers are in oro_events.
*/

%!  subscriber(?Subscriber, ?Queue, ?Thread, ?Owner) is nondet.
%
%   The live subscribers, exported for reading only: Subscriber is
%   subscriber(Name, Registry, OnOverflow), Queue its bounded queue (or
%   direct(Deliver) for an in_watcher subscriber, Thread then `none`),
%   Owner `caller` or `callback` (oro_subscribe/8).

:- dynamic
    subscriber/4,                   % Subscriber, Queue, Thread, Owner
    callback_subscriber/2,          % Id, Subscriber
    discarding/1,                   % Name of a subscriber being stopped
    pending_direct/3.               % Deliver, Id, Content

		 /*******************************
		 *         SUBSCRIBERS          *
		 *******************************/

%!  subscriber_create(:Deliver, -Subscriber, +Options, +Owner) is det.
%
%   Create a subscriber (see oro_subscriber_create/3).  Owner is
%   `caller` or `callback` (oro_subscribe/8: the events modules destroy
%   it on overflow, overflow/1, and on reset, oro_events_reset/0).

subscriber_create(Deliver, Subscriber, Options, Owner) :-
    strip_module(Deliver, _, Goal),
    must_be(callable, Goal),
    option(max_queue(Max), Options, 10000),
    must_be(positive_integer, Max),
    option(on_overflow(OnOverflow), Options, true),
    must_be(callable, OnOverflow),
    option(registry(Registry), Options, plain),
    must_be(oneof([plain, agent, internal]), Registry),
    option(in_watcher(InWatcher), Options, false),
    must_be(boolean, InWatcher),
    gensym(oro_subscriber_, Name),
    Subscriber = subscriber(Name, Registry, OnOverflow),
    (   InWatcher == true
    ->  Queue = direct(Deliver),
        Thread = none
    ;   message_queue_create(Queue, [max_size(Max)]),
        (   Owner == callback               % a planner's code reads the store
        ->  Deliver1 = deliver_reading(Deliver)
        ;   Deliver1 = Deliver
        ),
        thread_create(deliver_thread(Queue, Name, Deliver1), Thread, [])
    ),
    with_mutex(oro_events_delivery,
               assertz(subscriber(Subscriber, Queue, Thread, Owner))).

%!  subscriber_registry(+Subscriber, -Registry) is det.
%
%   Registry is the default registry of Subscriber.
%   @error type_error(oro_subscriber, Subscriber)

subscriber_registry(subscriber(_, Registry, _), Registry) :-
    !.
subscriber_registry(Subscriber, _) :-
    type_error(oro_subscriber, Subscriber).

%!  claim_subscriber(+Subscriber, -Queue, -Thread) is semidet.
%
%   Take Subscriber out of the table of live subscribers.  Who claims it
%   (a destroy, a reset, an overflow) stops its thread; the watcher
%   thread sends nothing more to it.

claim_subscriber(Subscriber, Queue, Thread) :-
    with_mutex(oro_events_delivery,
               ( retract(subscriber(Subscriber, Queue, Thread, _)),
                 retractall(callback_subscriber(_, Subscriber))
               )).

%!  stop_delivery(+Name, +Queue, +Thread, +How) is det.
%
%   End the delivery
%   thread of a claimed subscriber and free its queue.  How is
%   `deliver` (what is queued first), `discard` (dropped; a call of
%   Deliver in progress ends first) or `abort` (dropped, and a call in
%   progress is interrupted).  A thread stopping itself only notes it
%   is to end, detached, when its Deliver returns.

stop_delivery(Name, Queue, Thread, How) :-
    thread_self(Me),
    (   Thread == Me
    ->  mark_discarding(Name),
        thread_detach(Me),
        thread_at_exit(end_delivery(Name, Queue)),
        ignore(thread_send_message(Queue, '$stop', [timeout(0)]))
    ;   How == deliver
    ->  thread_send_message(Queue, '$stop'),
        thread_join(Thread, _),
        end_delivery(Name, Queue)
    ;   mark_discarding(Name),
        % When the queue is full the thread gets a message anyway and
        % sees it is discarding.
        ignore(thread_send_message(Queue, '$stop', [timeout(0)])),
        (   How == abort
        ->  catch(thread_signal(Thread, throw(oro_delivery_aborted)), _, true)
        ;   true
        ),
        thread_join(Thread, _),
        end_delivery(Name, Queue)
    ).

mark_discarding(Name) :-
    with_mutex(oro_events_delivery,
               (   discarding(Name)
               ->  true
               ;   assertz(discarding(Name))
               )).

end_delivery(Name, Queue) :-
    message_queue_destroy(Queue),
    with_mutex(oro_events_delivery, retractall(discarding(Name))).

deliver_thread(Queue, Name, Deliver) :-
    catch(deliver_loop(Queue, Name, Deliver), oro_delivery_aborted, true).

deliver_loop(Queue, Name, Deliver) :-
    thread_get_message(Queue, Message),
    (   Message == '$stop'
    ->  true
    ;   discarding(Name)
    ->  true
    ;   Message = event(Id, Content),
        catch(call(Deliver, Id, Content), E, delivery_error(E)),
        deliver_loop(Queue, Name, Deliver)
    ).

%   A callback of oro_subscribe/8 runs with no store rebuild in progress
%   (see oro_store_read/1).  A connection's delivery only writes to it:
%   it may wait for a slow client, and must not hold up a rebuild.

deliver_reading(Deliver, Id, Content) :-
    oro_store_read(call(Deliver, Id, Content)).

delivery_error(E) :-
    (   (   E == oro_delivery_aborted
        ;   E == '$aborted'
        ;   E = unwind(_)
        )
    ->  throw(E)
    ;   print_message(warning, E)
    ).

%!  note_callback(+Id, +Subscriber) is det.
%
%   A subscriber of oro_subscribe/8 is
%   noted with its watcher here, in the watcher thread, so that an
%   overflow right after the registration finds it.

note_callback(Id, Subscriber) :-
    (   subscriber(Subscriber, _, _, callback),
        \+ callback_subscriber(Id, Subscriber)
    ->  with_mutex(oro_events_delivery,
                   assertz(callback_subscriber(Id, Subscriber)))
    ;   true
    ).

%!  callback_subscribers(+Id, -Subscribers) is det.
%
%   Subscribers are the subscribers of oro_subscribe/8 on watcher Id.

callback_subscribers(Id, Subscribers) :-
    with_mutex(oro_events_delivery,
               findall(S, callback_subscriber(Id, S), Subscribers)).

%!  claim_callback_subscribers(-Stops) is det.
%
%   Claim every subscriber of
%   oro_subscribe/8 (a reset), as stop(Name, Queue, Thread) terms for
%   stop_delivery/4.

claim_callback_subscribers(Stops) :-
    findall(S, subscriber(S, _, _, callback), Subscribers),
    findall(stop(Name, Queue, Thread),
            ( member(S, Subscribers),
              S = subscriber(Name, _, _),
              claim_subscriber(S, Queue, Thread)
            ), Stops).

%!  run_direct_deliveries is det.
%
%   Deliveries to in_watcher subscribers run once the snapshot
%   transaction is over, so they may change the store.

run_direct_deliveries :-
    forall(retract(pending_direct(Deliver, Id, Content)),
           catch(call(Deliver, Id, Content), E,
                 print_message(warning, E))).

		 /*******************************
		 *           FIRINGS            *
		 *******************************/

%!  firings(+Type, +Trigger, +State0, +Outcome, -Contents, -Remove) is det.
%
%   The events a watcher sends when its state goes from State0 by
%   Outcome (ORO-SPEC §7.3), and whether it is then removed.

firings(fact_checking, Trigger, State0, truth(R), Contents, Remove) :-
    (   State0 == truth(true)
    ->  Last = true
    ;   Last = false
    ),
    fact_firing(Trigger, Last, R, Fire, Remove),
    (   Fire == true
    ->  Contents = [[]]
    ;   Contents = []
    ).
firings(new_instance, Trigger, _, diff(Added, Removed), Contents, Remove) :-
    instance_firing(Trigger, Added, Removed, Contents, Remove).
firings(new_class_instance, Trigger, _, diff(Added, _), Contents, Remove) :-
    (   Added \== [],
        memberchk(Trigger, [on_true, on_true_one_shot])
    ->  Contents = [Added],
        (   Trigger == on_true_one_shot
        ->  Remove = true
        ;   Remove = false
        )
    ;   Contents = [],
        Remove = false
    ).

fact_firing(on_true, Last, R, Fire, false) :-
    (   R == true, Last == false -> Fire = true ; Fire = false ).
fact_firing(on_false, Last, R, Fire, false) :-
    (   R == false, Last == true -> Fire = true ; Fire = false ).
fact_firing(on_toggle, Last, R, Fire, false) :-
    (   R \== Last -> Fire = true ; Fire = false ).
fact_firing(on_true_one_shot, _, R, Fire, Fire) :-
    (   R == true -> Fire = true ; Fire = false ).
fact_firing(on_false_one_shot, _, R, Fire, Fire) :-
    (   R == false -> Fire = true ; Fire = false ).

instance_firing(on_true, Added, _, Contents, false) :-
    non_empty(Added, Contents).
instance_firing(on_false, _, Removed, Contents, false) :-
    non_empty(Removed, Contents).
instance_firing(on_toggle, Added, Removed, Contents, false) :-
    non_empty(Removed, C1),
    non_empty(Added, C2),
    append(C1, C2, Contents).
instance_firing(on_true_one_shot, Added, _, Contents, Remove) :-
    non_empty(Added, Contents),
    one_shot(Contents, Remove).
instance_firing(on_false_one_shot, _, Removed, Contents, Remove) :-
    non_empty(Removed, Contents),
    one_shot(Contents, Remove).

non_empty([], []) :- !.
non_empty(Values, [Values]).

one_shot([], false) :- !.
one_shot(_, true).

%!  fire(+Id, +Content) is det.
%
%   Queue the firing to every subscriber, without
%   ever waiting.  A full queue drops its subscriber.

fire(Id, Content) :-
    (   watcher(Id, Model, _, _, _)
    ->  forall(oro_events:fired(Model, Id, Content), true)
    ;   true
    ),
    forall(subscription(Id, Subscriber),
           send_firing(Subscriber, Id, Content)).

:- multifile oro_events:fired/3.

%!  oro_events:fired(+Model, +Id, +Content) is nondet.
%
%   Multifile hook, called in the watcher thread each time watcher Id
%   of Model fires with Content (before its subscribers are sent it):
%   the web inspector's live feed listens there.  A clause must be
%   quick, must not block and must not throw.

send_firing(Subscriber, Id, Content) :-
    (   subscriber(Subscriber, Queue, _, _)
    ->  (   Queue = direct(Deliver)
        ->  assertz(pending_direct(Deliver, Id, Content))  % run after the snapshot
        ;   thread_send_message(Queue, event(Id, Content), [timeout(0)])
        ->  true
        ;   overflow(Subscriber)
        )
    ;   unsubscribe(Subscriber)                 % being destroyed
    ).

%   overflow(+Subscriber): Subscriber's queue is full.  It loses its
%   subscriptions and its on_overflow goal runs in a thread of its own
%   (for a subscriber of a connection, ending the connection).  A
%   subscriber of oro_subscribe/8 is destroyed too: its queued firings
%   are discarded, and its on_overflow goal is told which subscription
%   was dropped.

overflow(Subscriber) :-
    print_message(warning, format("oro: event subscriber ~w fell behind: \c
                                   dropped", [Subscriber])),
    unsubscribe(Subscriber),
    Subscriber = subscriber(Name, _, OnOverflow),
    (   subscriber(Subscriber, _, _, callback)
    ->  with_mutex(oro_events_delivery,
                   findall(I, callback_subscriber(I, Subscriber), Ids)),
        (   claim_subscriber(Subscriber, Queue, Thread)
        ->  mark_discarding(Name),
            (   Ids = [Id|_]
            ->  Subscription = oro_subscription(Id, Subscriber)
            ;   Subscription = none
            ),
            thread_create(callback_overflow(OnOverflow, Subscription,
                                            Name, Queue, Thread),
                          _, [detached(true)])
        ;   true                            % claimed by a destroy meanwhile
        )
    ;   thread_create(run_overflow_goal(OnOverflow), _, [detached(true)])
    ).

run_overflow_goal(Goal) :-
    catch(Goal, E, print_message(warning, E)),
    !.
run_overflow_goal(_).

callback_overflow(OnOverflow, Subscription, Name, Queue, Thread) :-
    (   strip_module(OnOverflow, _, true)
    ->  true
    ;   Subscription == none
    ->  true
    ;   run_overflow_goal(call(OnOverflow, Subscription))
    ),
    stop_delivery(Name, Queue, Thread, discard).
