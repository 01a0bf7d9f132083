:- module(oro_events,
          [ oro_events_start/0,
            oro_events_reset/0,
            oro_register_event/7,       % +Model, +Type, +Trigger, +Var, +Patterns, +Subscriber, -Id
            oro_register_event/8,       % +Model, +Type, +Trigger, +Var, +Patterns, +Subscriber, +Registry, -Id
            oro_clear_events/1,         % +Model
            oro_clear_events/2,         % +Model, +Registry
            oro_clear_event/2,          % +Model, +Id
            oro_clear_event/3,          % +Model, +Registry, +Id
            oro_watchers/2,             % +Model, -Watchers
            oro_subscriber_create/3,    % :Deliver, -Subscriber, +Options
            oro_subscriber_destroy/1,   % +Subscriber
            oro_subscriber_destroy/2,   % +Subscriber, +Options
            oro_subscribe/7,            % +Model, +Type, +Trigger, +Var, +Patterns, :Callback, -Id
            oro_subscribe/8,            % +Model, +Type, +Trigger, +Var, +Patterns, :Callback, -Subscription, +Options
            oro_unsubscribe/1,          % +IdOrSubscription
            oro_events_sync/0,
            oro_events_sync_sent/0,
            oro_events_sync_sent/1      % +Timeout
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(error)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(pairs)).
:- use_module(library(assoc)).
:- use_module(library(option)).
:- use_module(library(debug)).
:- use_module(library(settings)).
:- use_module(library(uuid)).
:- use_module(library(ordsets)).
:- use_module(library(oro/oro_names)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/reason/oro_reason)).
:- use_module(library(oro/oro_query)).
:- use_module(library(oro/parse/oro_parse)).

:- meta_predicate
    oro_subscriber_create(2, -, :),
    oro_subscribe(+, +, +, +, +, 2, -),
    oro_subscribe(+, +, +, +, +, 2, -, :).

/** <module> Events: watchers re-checked after every change

Robots react to the world through events: "tell me when an Artifact is
at the kitchen table".  A *watcher* is a pattern over a model with a
type and a trigger (ORO-SPEC §7):

  - `fact_checking`: the patterns (a conjunction) hold or not;
  - `new_instance`: the values a variable takes over the patterns;
  - `new_class_instance`: the instances of a class;

and triggers `on_true`, `on_true_one_shot`, `on_false`,
`on_false_one_shot`, `on_toggle`.  Identical watchers are shared: a
second registration returns the id of the first and adds a subscriber.

How changes reach watchers, exactly once and in order:

  - An rdf_monitor/2 callback, run by the writing thread when a
    transaction commits, only notes which models and predicates it
    touched (and whether the schema changed) and the changed triples
    themselves, up to 1,000 a transaction; at the end of the
    transaction it takes an rdf_db snapshot and queues one `change`
    message.  It never evaluates anything.
  - One watcher thread takes the changes in commit order and evaluates,
    inside the snapshot of each change, the watchers that change may
    affect.  So every transition is seen, even when changes follow
    each other faster than they are evaluated, and the answer does not
    depend on timing.
  - Registration is queued the same way, with a snapshot taken under
    the store's write lock, so the initial state of a watcher is the
    state right before the next change.
  - Firings go to subscribers.  A subscriber owns a bounded queue and a
    delivery thread that calls its Deliver goal: a slow subscriber
    never blocks writers, the watcher thread or other subscribers.  When
    a subscriber's queue is full it has fallen too far behind: it is
    dropped (its subscriptions are removed and its overflow goal, for a
    socket the closing of the connection, is run), so it never silently
    misses an event and stays subscribed.  Who destroys the subscriber
    (stops its thread, frees its queue) depends on who owns it: one made
    by oro_subscriber_create/3 belongs to its creator (a connection
    destroys its own when it closes); one made by oro_subscribe/8 for a
    planner belongs to this module, which destroys it on overflow (its
    queued firings are then discarded) and on reset
    (oro_events_reset/0), as well as on oro_unsubscribe/1.

The watcher thread owns all watcher state; other threads only send it
messages.  Its own queue (changes and requests) is *unbounded*, so that
writers never wait for it, and *each queued change holds an rdf_db
snapshot* (rdf_snapshot/1) until it is processed: while the watcher
thread is behind a burst of writes, rdf_db keeps every triple version
those snapshots may see.  Memory then grows with the backlog (not with
the number of watchers) and is given back as it is processed;
oro_events_sync/0 waits for it.  (That a snapshot keeps every triple it
may see relies on the store's GC pin: see oro_store.)

When its queue is empty, the watcher thread compiles ahead the shared
schema tables (oro_reason) of each model that has none for the
current schema generation: `myself` at the start, an agent's model
once it is created, every model again after a schema change.  Without
this, the first query of a model after such a change compiled them
itself (3-4 ms on the bench's world).  A message that arrives while
the thread compiles waits for that one model, and a compilation that
a schema change made stale is not retried before that change is over
(the store's schema_hook/1 then sends the thread a message).

## Incremental evaluation

With 1,000 watchers a change must not cost 1,000 evaluations.  Each
watcher keeps its state (the truth of its patterns, or its values, one
fact a value) and is indexed, when registered and after each schema
change, by what may change it:

  - *dependencies*: the predicates whose triples can change its
    solutions, through sub-properties, inverses, symmetry,
    transitivity, domains and ranges (oro_pattern_dependencies/3), or
    `any`.  Writers read them to decide whether to send a change at all.
  - *triggers*: a dependency with an *anchor*.  Without transitivity a
    pattern instance `S P O` that a triple `s q o` makes true (or
    false) has S and O among s, o and their owl:sameAs individuals, so
    `?x isOn table_3` is only triggered by a change mentioning
    `table_3`: anchor res(table_3).  A type `?x rdf:type Cup` is
    triggered by `s rdf:type D` only when D is under Cup:
    anchor class(Cup).  The watcher thread looks the triggers of each
    changed triple up by hash (predicate, anchor), so 1,000 watchers on
    `isOn` with different tables cost one lookup each change; a type
    triple's class anchors by each super-class of its class
    (class_watcher/4).  When every trigger on rdf:type of a model's
    watchers is a class, the writers make that lookup themselves
    (type_filter/3): the objects perception types, which no watcher of
    theirs asks for, are neither queued nor sent.
  - a *plan*: how each pattern can gain solutions from added triples.

A triggered watcher is then evaluated from the change's triples
(*seeded*): the inference closure only grows when triples are added,
so a new solution must use, in some pattern, an instance that the
change made true; each pattern the change concerns is solved with its
subject and object bound to the resources of a changed triple (both
ways round, and their sameAs individuals), or, through a transitive
property, to what reaches them and what they reach; the other patterns
are then solved with those bindings.  A removed triple can only make
values false whose solutions used it: when the variable is the subject
or object of the pattern concerned, only the values among the
resources of the removed triple are checked again.

Full evaluation remains, always correct, where seeding is not sound or
not worth it: a schema change (or a change of the ontology layer), a
transaction changing more than 1,000 triples, an rdf_update, a
pattern with a variable predicate, on rdfs:subClassOf,
rdfs:subPropertyOf or owl:sameAs, a type with neither end given, or
whose subject and object are one variable (see pattern_kind/6), a
removal under a transitive property or whose lost values cannot be
narrowed, a true fact_checking watcher losing a triple it depends on,
one not evaluated yet, and too many seeds (more than 2,000).

## Settings

  - `oro_events:incremental` (default `true`): `false` forces full
    evaluation of every watcher the index selects.
  - `oro_events:index` (default `true`): `false` is a reference mode
    that ignores the index altogether: every change is sent to the
    watcher thread, the schemas of the models it touches are compiled
    again, and every watcher of those models is evaluated in full.
    Slow; it exists to check the index.
  - `oro_events:warm_schemas` (default `true`): `false` leaves the
    schema tables to be compiled by the first query that needs them.

The tests compare the three on random changes over a schema with
sub-properties, inverses, symmetric and transitive properties, domains
and ranges.
*/

:- setting(incremental, boolean, true,
           'Evaluate watchers from the changed triples where sound; \c
            false re-evaluates every affected watcher in full').
:- setting(index, boolean, true,
           'Select the watchers a change may affect by their dependencies; \c
            false (a reference for tests) evaluates every watcher of the \c
            changed models in full at every change').
:- setting(warm_schemas, boolean, true,
           'The watcher thread, when idle, compiles the schema tables of \c
            the models that have none for the current schema (false: the \c
            first query of a model after a schema change compiles them)').

:- dynamic
    watcher/5,                      % Id, Model, Registry, Spec, Query
    watcher_variant/2,              % Key, Id (see variant_key/4)
    watcher_seq/2,                  % Id, Seq (registration order)
    watcher_state/2,                % Id, unknown|truth(Bool)|values
    watcher_value/2,                % Value, Id
    watcher_dep/3,                  % Model, PredicateOrAny, Id
    watcher_trigger/5,              % Key, Model, Predicate, Anchor, Id
    watcher_type_class/3,           % Class, Model, Id
    watcher_type_open/2,            % Model, Id
    watcher_plan/2,                 % Id, Plan
    subscription/2,                 % Id, Subscriber
    subscriber/4,                   % Subscriber, Queue, Thread, Owner
    callback_subscriber/2,          % Id, Subscriber
    discarding/1,                   % Name of a subscriber being stopped
    pending_direct/3,               % Deliver, Id, Content
    model_schema/2.                 % Model, Key (the watcher thread's)

%   Bounds of incremental evaluation: the triples a transaction may
%   change and still be evaluated from its triples, and the seeds a
%   watcher may be solved with in one change.

max_delta(1000).
max_seeds(2000).

		 /*******************************
		 *            START             *
		 *******************************/

%!  oro_events_start is det.
%
%   Start the watcher thread and the store monitor, if not running.

oro_events_start :-
    with_mutex(oro_events,
               (   watcher_running
               ->  true
               ;   message_queue_create(_, [alias(oro_watcher_queue)]),
                   thread_create(watcher_start, _,
                                 [alias(oro_watcher), detached(false)]),
                   monitor_mask(Mask),
                   rdf_monitor(oro_events:monitor, Mask)
               )).

monitor_mask([-all, +assert, +retract, +update, +transaction]).

%   A store rebuild (oro_store_rebuild/0) must not reset rdf_db while
%   changes wait in the watcher's queue with their snapshots; the
%   watchers must not see the store emptied and filled again (with the
%   same triples: their state stays right).

%   Every schema change, once over, sends the watcher thread a message,
%   after which it compiles ahead (warm_while_idle/0).  The messages of
%   the changes' triples do not do: a write's commit sends them before
%   the write bumps the schema generation for the last time, and a
%   rolled-back write, an ontology load or a reset send none.

:- multifile oro_store:schema_hook/1.

oro_store:schema_hook(changed) :-
    setting(warm_schemas, true),
    watcher_running,
    thread_send_message(oro_watcher_queue, schema_changed).

:- multifile oro_store:rebuild_hook/1.

oro_store:rebuild_hook(blocked(Deadline)) :-
    watcher_running,
    get_time(Now),
    Timeout is max(0, Deadline - Now),
    \+ call_watcher(sync, true, [timeout(Timeout)]).
oro_store:rebuild_hook(suspend) :-
    (   watcher_running
    ->  rdf_monitor(oro_events:monitor, [-all])
    ;   true
    ).
oro_store:rebuild_hook(resume) :-
    (   watcher_running
    ->  monitor_mask(Mask),
        rdf_monitor(oro_events:monitor, Mask)
    ;   true
    ).

watcher_running :-
    catch(thread_property(oro_watcher, status(running)), _, fail).

%!  oro_events_reset is det.
%
%   Forget every watcher (reset): their ids become unknown.  The
%   subscribers of oro_subscribe/8 are destroyed: the firings they have
%   queued are discarded and, when this returns, their threads have
%   ended (it waits for a call of a callback in progress; a callback
%   calling oro_reset/0 ends its own thread once it returns).
%   Subscribers of oro_subscriber_create/3 stay, with no subscriptions:
%   their creators own them.

oro_events_reset :-
    call_watcher(reset, stop(Stops)),
    forall(member(stop(Name, Queue, Thread), Stops),
           stop_delivery(Name, Queue, Thread, discard)).

%!  oro_events_sync is det.
%
%   Wait until the watcher thread has processed every change committed
%   before the call (its events are then queued to the subscribers).

oro_events_sync :-
    call_watcher(sync).

%!  oro_events_sync_sent is det.
%
%   Wait until the watcher thread has processed the changes the calling
%   thread committed and sent it since its last call (the changes no
%   watcher depends on are not sent): their events are then queued to
%   the subscribers, and delivered to those made with
%   in_watcher(true).  True at once when it sent none, so a server
%   thread may call it after every request at no cost to a request that
%   fired nothing.

oro_events_sync_sent :-
    (   nb_current(oro_events_sent, true)
    ->  nb_setval(oro_events_sent, false),
        oro_events_sync
    ;   true
    ).

%!  oro_events_sync_sent(+Timeout) is semidet.
%
%   As oro_events_sync_sent/0, waiting Timeout seconds at most: fails
%   if the watcher thread has not processed those changes by then (it
%   goes on, and their events are queued to the subscribers when it is
%   done).

oro_events_sync_sent(Timeout) :-
    must_be(number, Timeout),
    (   nb_current(oro_events_sent, true)
    ->  nb_setval(oro_events_sent, false),
        call_watcher(sync, true, [timeout(Timeout)])
    ;   true
    ).

call_watcher(Request) :-
    call_watcher(Request, true).

call_watcher(Request, Reply) :-
    call_watcher(Request, Reply, []).

%   call_watcher(+Request, -Reply, +Options): fails if the reply does not
%   come within Options' timeout(Seconds) (it is then left in the
%   caller's queue, where no later call looks for its tag).

call_watcher(Request, Reply, Options) :-
    oro_events_start,
    thread_self(Me),
    forget_late_replies(Me),
    gensym(oro_reply_, Tag),
    thread_send_message(oro_watcher_queue, call(Request, Me, Tag)),
    (   thread_get_message(Me, reply(Tag, Result), Options)
    ->  true
    ;   late_tags(Late),
        nb_setval(oro_events_late, [Tag|Late]),
        fail
    ),
    (   Result = error(E)
    ->  throw(E)
    ;   Result = Reply
    ).

%   forget_late_replies(+Me): take from the queue of the calling thread
%   the replies that came after their call_watcher/3 gave up waiting
%   (as they come; the others are looked for again at the next call).

forget_late_replies(Me) :-
    late_tags(Late),
    (   Late == []
    ->  true
    ;   exclude(late_reply_taken(Me), Late, Left),
        nb_setval(oro_events_late, Left)
    ).

late_reply_taken(Me, Tag) :-
    thread_get_message(Me, reply(Tag, _), [timeout(0)]).

%   late_tags(-Tags): the tags of the calling thread's replies still
%   to come after their call gave up (a global variable of the thread).

late_tags(Tags) :-
    (   nb_current(oro_events_late, Tags0)
    ->  Tags = Tags0
    ;   Tags = []
    ).

		 /*******************************
		 *           MONITOR            *
		 *******************************/

%   monitor(+Event): called by rdf_db in the writing thread when a
%   transaction commits.  It must stay cheap and never fail or throw.
%   What a commit notes is kept by the writing thread, in its global
%   variables (oro_events_in_commit, oro_events_touched,
%   oro_events_touched_schema, and the delta's size and overflow) and,
%   for the triples of the delta, in a message queue of its own (see
%   delta_queue/1), not in facts: a clause asserted and retracted by
%   every write, or every triple, is work for SWI-Prolog's clause
%   garbage collector, which then also runs atom GC (see oro_store,
%   "Writes leave no clause behind").

:- public monitor/1.

monitor(Event) :-
    catch(monitor_(Event), E, print_message(warning, E)),
    !.
monitor(_).

monitor_(transaction(begin(0), _)) :-
    !,
    monitor_unpin,
    nb_setval(oro_events_in_commit, true).
monitor_(transaction(end(0), _)) :-
    !,
    nb_setval(oro_events_in_commit, false),
    flush_changes.
monitor_(transaction(_, _)) :-
    !.
monitor_(assert(S, P, O, G)) :-
    !,
    note(G, S, P, O, add).
monitor_(retract(S, P, O, G)) :-
    !,
    note(G, S, P, O, del).
monitor_(update(S, P, O, G, Action)) :-
    !,
    updated(Action, S, P, O, G, S1, P1, O1, G1),
    note(G, S, P, O, update),
    note(G1, S1, P1, O1, update).
monitor_(_).

updated(subject(S1), _, P, O, G, S1, P, O, G).
updated(predicate(P1), S, _, O, G, S, P1, O, G).
updated(object(O1), S, P, _, G, S, P, O1, G).
updated(graph(G1), S, P, O, _, S, P, O, G1).

%   note(+Source, +S, +P, +O, +Sign): a triple of Source was added,
%   removed or updated.  Nothing is noted while nobody watches.

note(Source, S, P, O, Sign) :-
    (   watching
    ->  true
    ;   pending
    ),
    !,
    source_graph(Source, G),
    touch(G, P, Model, Layer, Followed0),
    triple_followed(Followed0, Model, Sign, O, Followed),
    (   oro_schema_triple(P, O)
    ->  nb_setval(oro_events_touched_schema, true)
    ;   true
    ),
    note_delta(Followed, Model, Layer, Sign, S, P, O),
    (   nb_current(oro_events_in_commit, true)
    ->  true
    ;   flush_changes                       % a write outside a transaction
    ).
note(_, _, _, _, _).

source_graph(G:_, G) :- !.
source_graph(G, G).

%   touch(+G, +P, -Model, -Layer, -Followed): note that the transaction
%   changed a triple of P in graph G, which is the Layer of Model;
%   Followed is `true` if the triples of the pair must go in the delta
%   (see note_delta/7), classes(Key) if that is decided for each
%   (triple_followed/5).  What is noted is the writing thread's global
%   variable oro_events_touched, a list of t(G, P, Model, Layer,
%   Followed) in reverse order, one per graph and predicate: there are
%   few in a transaction, and the graph's model and whether a watcher
%   follows P are worked out once for all the triples of the pair.
%   (No registration changes what the watchers follow meanwhile: it
%   takes the `oro_write` mutex, which the writer holds.)

touch(G, P, Model, Layer, Followed) :-
    (   nb_current(oro_events_touched, Touched)
    ->  true
    ;   Touched = []
    ),
    (   memberchk(t(G, P, Model0, Layer0, Followed0), Touched)
    ->  Model = Model0,
        Layer = Layer0,
        Followed = Followed0
    ;   graph_model(G, Model, Layer),
        monitor_pin,
        pair_followed(Model, P, Followed),
        nb_setval(oro_events_touched,
                  [t(G, P, Model, Layer, Followed)|Touched])
    ).

%   pair_followed(+Model, +P, -Followed): whether a watcher follows the
%   triples of P in Model: `true`, `false`, or, for rdf:type, classes(Key)
%   when the watchers that follow it are all anchored by classes (see
%   type_filter/3).

pair_followed('$none', _, false) :-
    !.
pair_followed('$all', _, true) :-
    !.
pair_followed(Model, P, Followed) :-
    (   pending
    ->  Followed = true
    ;   depended_on(Model, P)
    ->  (   type_filter(Model, P, Key)
        ->  Followed = classes(Key)
        ;   Followed = true
        )
    ;   Followed = false
    ).

%   type_filter(+Model, +P, -Key): P is rdf:type and every trigger of
%   Model's watchers on it is a class anchor: a type triple `s rdf:type
%   D` then only concerns a watcher when D is under one of their
%   classes (see triggered/6, which decides the same in the watcher
%   thread), which is looked up for each triple in the schema tables
%   Key, if compiled already.  Perception types every object it sees,
%   and the agents' internal watcher follows rdf:type for `Agent` only:
%   its typed objects need neither go in the delta nor wake the watcher
%   thread.  Only where the watcher thread would select the watchers by
%   their triggers (the incremental mode).  The monitor never compiles
%   the schema: if the shared tables are stale (a schema change anywhere
%   makes them so, as an agent's model created), the pair is followed
%   as a whole, and the watcher thread is asked to compile them
%   (warm(Model)) for the next writes.  The tables of Key are read until
%   the commit ends, by triple_followed/5: the writing thread holds a pin
%   on the shared tables from before it reads Key (touch/5) until then
%   (monitor_pin/0), so that a schema change in another thread does not
%   free them under it.

type_filter(Model, P, Key) :-
    rdf_equal(P, rdf:type),
    \+ watcher_dep(Model, any, _),
    \+ watcher_type_open(Model, _),
    setting(incremental, true),
    setting(index, true),
    (   oro_compiled_schema(Model, Key0)
    ->  Key = Key0
    ;   thread_send_message(oro_watcher_queue, warm(Model)),
        fail
    ).

%   monitor_pin, monitor_unpin: the writing thread's pin on the shared
%   schema tables (oro_schema_pin/0), taken before the monitor may read
%   a key of them (a pair first noted, touch/5), at most once a commit,
%   and left when the commit's notes are taken (take_touched/3), once
%   no key is kept; noted in its global variable oro_events_pinned.  One
%   left by a commit that did not end is left at the next one's start.

monitor_pin :-
    (   nb_current(oro_events_pinned, true)
    ->  true
    ;   sig_atomic(( oro_schema_pin,
                     nb_setval(oro_events_pinned, true)
                   ))
    ).

monitor_unpin :-
    (   nb_current(oro_events_pinned, true)
    ->  sig_atomic(( nb_setval(oro_events_pinned, false),
                     oro_schema_unpin
                   ))
    ;   true
    ).

%   triple_followed(+PairFollowed, +Model, +Sign, +O, -Followed): whether
%   the triple goes in the delta.  For classes(Key), a type triple does
%   if its class is under a watched class (or if it is an update, which
%   the watcher thread evaluates in full); it is then noted as
%   followed, for take_touched/3.

triple_followed(classes(Key), Model, Sign, O, Followed) :-
    !,
    (   (   Sign == update
        ;   class_watcher(Key, Model, O, _)
        )
    ->  nb_setval(oro_events_followed_type, true),
        Followed = true
    ;   Followed = false
    ).
triple_followed(Followed, _, _, _, Followed).

%   take_touched(-Touched, -Followed, -Schema): the Model-P pairs noted
%   in this transaction, each once, in the order noted; whether a
%   watcher follows one of them (touch/5), and whether a schema triple
%   changed.  What was noted is reset, and the pin on the shared schema
%   tables that its keys needed is left (monitor_unpin/0).

take_touched(Touched, Followed, Schema) :-
    (   nb_current(oro_events_touched, Noted)
    ->  reverse(Noted, InOrder),
        model_pairs(InOrder, [], Touched)
    ;   Noted = [],
        Touched = []
    ),
    (   (   memberchk(t(_, _, _, _, true), Noted)
        ;   nb_current(oro_events_followed_type, true)
        )
    ->  Followed = true
    ;   Followed = false
    ),
    (   nb_current(oro_events_touched_schema, true)
    ->  Schema = true
    ;   Schema = false
    ),
    nb_setval(oro_events_touched, []),
    nb_setval(oro_events_followed_type, false),
    nb_setval(oro_events_touched_schema, false),
    monitor_unpin.

model_pairs([], _, []).
model_pairs([t(_, P, Model, _, _)|Noted], Seen, Pairs) :-
    (   memberchk(Model-P, Seen)
    ->  Pairs = Pairs1
    ;   Pairs = [Model-P|Pairs1]
    ),
    model_pairs(Noted, [Model-P|Seen], Pairs1).

graph_model(G, Model, Layer) :-
    (   oro_graph_layer(G, Model0, Layer0)
    ->  Model = Model0,
        Layer = Layer0
    ;   oro_ontology_graph(G)
    ->  Model = '$all',
        Layer = ontology
    ;   Model = '$none',
        Layer = none
    ).

%   note_delta(+Followed, +Model, +Layer, +Sign, +S, +P, +O): record
%   the triple as added to or removed from the triples visible in Model
%   (a triple put in a model's mask is removed from it).  Past
%   max_delta/1 triples, or for a change the watchers cannot follow
%   triple by triple (the ontology layer, rdf_update), the list is
%   dropped: the change is then evaluated in full.  A triple is recorded
%   only if Followed (see touch/5): a triple of a model none of whose
%   watchers depends on its predicate is not, as no watcher would look
%   at it (concerned/3, triggered/6).  What the watchers depend on is
%   depended_on/2, which also decides whether the change is sent at all
%   (flush_changes/0); while the watcher thread has registrations or
%   schema changes to process, every triple is recorded.

note_delta(Followed, Model, Layer, Sign0, S, P, O) :-
    (   Followed == false
    ->  true
    ;   nb_current(oro_events_delta_overflow, true)
    ->  true
    ;   delta_sign(Model, Layer, Sign0, Sign),
        delta_room
    ->  delta_queue(Queue),
        thread_send_message(Queue, d(Model, Sign, S, P, O))
    ;   delta_queue(Queue),
        oro_drain_queue(Queue, _),
        nb_setval(oro_events_delta_size, 0),
        nb_setval(oro_events_delta_overflow, true)
    ).

%   delta_queue(-Queue): the writing thread's queue of the triples noted
%   in the current transaction, made on its first use (an anonymous
%   queue, reclaimed with the thread's global variables).

delta_queue(Queue) :-
    (   nb_current(oro_events_delta_queue, Queue0)
    ->  Queue = Queue0
    ;   message_queue_create(Queue),
        nb_setval(oro_events_delta_queue, Queue)
    ).

delta_sign(Model, Layer, Sign0, Sign) :-
    Model \== '$all',
    (   Sign0 == update
    ->  fail
    ;   Layer == mask
    ->  opposite(Sign0, Sign)
    ;   Sign = Sign0
    ).

opposite(add, del).
opposite(del, add).

%   delta_room: the delta may take one more triple.  Its size is
%   counted in a global variable of the writing thread (a counter fact
%   would cost a retract and an assert a triple).

delta_room :-
    (   nb_current(oro_events_delta_size, N0)
    ->  true
    ;   N0 = 0
    ),
    max_delta(Max),
    N0 < Max,
    N is N0 + 1,
    nb_setval(oro_events_delta_size, N).

flush_changes :-
    take_touched(Touched, Followed, Schema),
    take_delta(Delta),
    (   Touched == []
    ->  true
    ;   (   Schema == true
        ;   pending
        ;   Followed == true
        ;   \+ setting(index, true)           % the reference mode
        )
    ->  (   Schema == true
        ->  flag(oro_events_pending, N, N+1)
        ;   true
        ),
        rdf_snapshot(Snapshot),
        thread_send_message(oro_watcher_queue,
                            change(Snapshot, Touched, Schema, Delta)),
        nb_setval(oro_events_sent, true)    % see oro_events_sync_sent/0
    ;   true
    ).

%   take_delta(-Delta): the triples noted in this transaction, as
%   d(Model, Sign, S, P, O) terms, or `full`.

take_delta(Delta) :-
    nb_setval(oro_events_delta_size, 0),
    (   nb_current(oro_events_delta_overflow, true)
    ->  nb_setval(oro_events_delta_overflow, false),
        Delta = full
    ;   nb_current(oro_events_delta_queue, Queue)
    ->  oro_drain_queue(Queue, Delta)
    ;   Delta = []
    ).

%   A change that no watcher depends on (none of its Model-P pairs
%   followed, see touch/5) is not sent at all.  The
%   dependencies are those of the watchers the watcher thread knows, so
%   while it has not yet processed a registration or a schema change
%   (which may change dependencies) every change is sent: the counter
%   oro_events_pending is raised, under the store's write lock, when one
%   is queued and lowered by the watcher thread once it is done.

pending :-
    flag(oro_events_pending, N, N),
    N > 0.

%   depended_on(+Model, +P): some watcher of Model depends on triples
%   of predicate P (or on any change), as the watcher thread last
%   indexed it (set_index/3).

depended_on(Model, P) :-
    (   watcher_dep(Model, any, _)
    ;   watcher_dep(Model, P, _)
    ),
    !.

		 /*******************************
		 *         REGISTRATION         *
		 *******************************/

%!  oro_register_event(+Model, +Type, +Trigger, +Var, +Patterns,
%!                     +Subscriber, -Id) is det.
%
%   Register a watcher on Model and subscribe Subscriber to it.  Type
%   and Trigger are names as ORO spells them, in any case
%   (`NEW_INSTANCE`, `on_true`); Var is the variable of a
%   `new_instance` watcher (`o` or `?o`, or with rdf/3 term patterns a
%   Prolog variable of them; ignored by the other types); Patterns are
%   statement texts or rdf/3 terms (a `new_class_instance` watcher takes
%   one class name).  Id is the id of the watcher (a UUID atom): that
%   of an identical watcher (a variant) if one exists.  The registry of
%   the watcher is the Subscriber's `registry` (see
%   oro_subscriber_create/3).
%
%   @error domain_error(oro_event_type, Type)
%   @error domain_error(oro_event_trigger, Trigger)
%   @error domain_error(oro_event_variable, Var) for a `new_instance`
%          watcher without a variable.
%   @error oro_event_registration(Message) for a bad pattern.

oro_register_event(Model, Type, Trigger, Var, Patterns, Subscriber, Id) :-
    subscriber_registry(Subscriber, Registry),
    oro_register_event(Model, Type, Trigger, Var, Patterns, Subscriber,
                       Registry, Id).

%!  oro_register_event(+Model, +Type, +Trigger, +Var, +Patterns,
%!                     +Subscriber, +Registry, -Id) is det.
%
%   As oro_register_event/7, the watcher going to Registry (`plain`,
%   `agent` or `internal`) whatever the subscriber's default: one
%   subscriber (one connection) may register in several registries and
%   still receives all its events in commit order.

oro_register_event(Model0, Type0, Trigger0, Var0, Patterns, Subscriber,
                   Registry, Id) :-
    oro_resolve_model(Model0, Model),
    event_type(Type0, Type),
    event_trigger(Trigger0, Trigger),
    must_be(list, Patterns),
    must_be(oneof([plain, agent, internal]), Registry),
    event_var(Type, Var0, Var),
    subscriber_registry(Subscriber, _),
    watcher_query(Type, Model, Var, Patterns, Query),
    Spec = spec(Type, Trigger, Var, Patterns),
    oro_events_start,
    thread_self(Me),
    gensym(oro_reply_, Tag),
    with_mutex(oro_write,
               ( rdf_snapshot(Snapshot),
                 flag(oro_events_pending, N, N+1),
                 thread_send_message(oro_watcher_queue,
                                     call(register(Model, Registry, Spec, Query,
                                                   Subscriber, Snapshot),
                                          Me, Tag))
               )),
    thread_get_message(reply(Tag, Result)),
    (   Result = error(E)
    ->  throw(E)
    ;   Result = id(Id)
    ).

event_type(Text, Type) :-
    must_be(text, Text),
    atom_string(Atom, Text),
    downcase_atom(Atom, Type),
    (   memberchk(Type, [fact_checking, new_instance, new_class_instance])
    ->  true
    ;   domain_error(oro_event_type, Text)
    ).

event_trigger(Text, Trigger) :-
    must_be(text, Text),
    atom_string(Atom, Text),
    downcase_atom(Atom, Trigger),
    (   memberchk(Trigger, [on_true, on_true_one_shot, on_false,
                            on_false_one_shot, on_toggle])
    ->  true
    ;   domain_error(oro_event_trigger, Text)
    ).

event_var(new_instance, Var0, Var) :-
    !,
    (   var(Var0)                       % a variable of term patterns
    ->  Var = Var0
    ;   text(Var0),
        atom_string(A, Var0),
        normalize_space(atom(A1), A),
        (   sub_atom(A1, 0, 1, _, ?)
        ->  sub_atom(A1, 1, _, 0, Var)
        ;   Var = A1
        ),
        Var \== ''
    ->  true
    ;   domain_error(oro_event_variable, Var0)
    ).
event_var(_, _, '').

text(X) :- string(X), !.
text(X) :- atom(X).

%   watcher_query(+Type, +Model, +Var, +Patterns, -Query): the query a
%   watcher evaluates, query(Template, Triples), parsed once.  Template
%   is the variable whose values a new_instance watcher follows (`none`
%   if the patterns do not use it, or for fact_checking); a
%   new_class_instance watcher follows X in `?X rdf:type Class`.

watcher_query(new_class_instance, Model, _, Patterns, query(X, [rdf(X, Type, Class)])) :-
    !,
    (   Patterns = [Name]
    ->  true
    ;   length(Patterns, N),
        throw(error(oro_event_registration(class_pattern(N)), _))
    ),
    oro_name_class(Name, Class),
    rdf_equal(rdf:type, Type),
    (   oro_class(Model, Class)
    ->  true
    ;   throw(error(oro_event_registration(unknown_class(Name)), _))
    ).
watcher_query(Type, _, Var, Patterns, query(Template, Triples)) :-
    catch(oro_statements(Patterns, Triples, Bindings), error(Formal, _),
          throw(error(oro_event_registration(pattern(Formal)), _))),
    (   Type == new_instance,
        var_template(Var, Triples, Bindings, Template0)
    ->  Template = Template0
    ;   Template = none
    ).

%   var_template(+Var, +Triples, +Bindings, -Template): the variable of
%   the patterns that Var names: a variable name of text patterns, or a
%   Prolog variable of term patterns.

var_template(Var, Triples, _, Var) :-
    var(Var),
    !,
    term_variables(Triples, Vars),
    member(V, Vars),
    V == Var,
    !.
var_template(Name, _, Bindings, Template) :-
    memberchk(Name=Template, Bindings).

oro_name_class(Name, Class) :-
    (   text(Name)
    ->  oro_name_iri(Name, Class)
    ;   oro_resource(Name, Class)
    ).

%!  oro_clear_events(+Model) is det.
%
%   Remove every watcher of Model that clients registered, with or
%   without an agent (registries `plain` and `agent`): ORO's
%   clearEvents() on the robot's model (ORO-SPEC §7.1), which also
%   removes what registerEventForAgent(myself, ...) registered, as
%   pyoro's subscribe() does.  oro's own (`internal`) watchers stay.

oro_clear_events(Model) :-
    oro_clear_events(Model, plain),
    oro_clear_events(Model, agent).

%!  oro_clear_events(+Model, +Registry) is det.
%
%   Remove every watcher of Model in Registry: `plain` (registerEvent)
%   or `agent` (registerEventForAgent, ORO's clearEventsForAgent()).

oro_clear_events(Model0, Registry) :-
    oro_resolve_model(Model0, Model),
    must_be(oneof([plain, agent, internal]), Registry),
    call_watcher(clear(Model, Registry)).

%!  oro_clear_event(+Model, +Id) is det.
%
%   Remove the watcher Id of Model, whatever its registry: ORO's
%   clearEvent(id).  Id is a UUID in either case.
%   @error existence_error(event, Id) if there is none.
%   @error domain_error(uuid, Id) if Id is not a UUID.

oro_clear_event(Model0, Id0) :-
    oro_resolve_model(Model0, Model),
    event_id(Id0, Id),
    call_watcher(clear_one(Model, _, Id)).

%!  oro_clear_event(+Model, +Registry, +Id) is det.
%
%   Remove the watcher Id of Model if it is in Registry: ORO's
%   clearEvent(agent, id) is oro_clear_event(Agent, agent, Id), which
%   only removes what registerEventForAgent registered on that agent's
%   model, as clearEventsForAgent() does (ORO-SPEC §7.1 keeps the
%   registries apart).
%   @error existence_error(event, Id) if Model has no watcher Id in
%          Registry (a watcher of another registry or model is left).
%   @error domain_error(uuid, Id) if Id is not a UUID.

oro_clear_event(Model0, Registry, Id0) :-
    oro_resolve_model(Model0, Model),
    must_be(oneof([plain, agent, internal]), Registry),
    event_id(Id0, Id),
    call_watcher(clear_one(Model, Registry, Id)).

%   event_id(+Text, -Id): Id is the watcher id Text names: a UUID in
%   hexadecimal groups of 8-4-4-4-12 digits, in either case (as Java's
%   UUID.fromString() takes it), given in lower case as registration
%   answers it.

event_id(Id0, Id) :-
    must_be(text, Id0),
    atom_string(Atom, Id0),
    downcase_atom(Atom, Id),
    (   split_string(Id, "-", "", Groups),
        maplist(string_length, Groups, [8, 4, 4, 4, 12]),
        atom_codes(Id, Codes),
        forall(member(C, Codes),
               ( C == 0'-
               ; between(0'0, 0'9, C)
               ; between(0'a, 0'f, C)
               ))
    ->  true
    ;   domain_error(uuid, Id0)
    ).

%!  oro_watchers(+Model, -Watchers) is det.
%
%   Watchers of Model, as watcher(Id, Type, Trigger, Var, Patterns,
%   Subscribers) terms, Subscribers being their number; oro's own
%   (`internal`) watchers are not listed.

oro_watchers(Model0, Watchers) :-
    oro_resolve_model(Model0, Model),
    findall(watcher(Id, Type, Trigger, Var, Patterns, N),
            ( watcher(Id, Model, Registry, spec(Type, Trigger, Var, Patterns), _),
              Registry \== internal,
              aggregate_all(count, subscription(Id, _), N)
            ),
            Watchers).

		 /*******************************
		 *          SUBSCRIBERS         *
		 *******************************/

:- predicate_options(oro_subscriber_create/3, 3,
                     [ max_queue(positive_integer),
                       on_overflow(callable),
                       registry(oneof([plain, agent, internal])),
                       in_watcher(boolean)
                     ]).

%!  oro_subscriber_create(:Deliver, -Subscriber, +Options) is det.
%
%   Create a subscriber: a bounded queue and a thread calling
%   call(Deliver, Id, Content) for each firing of the watchers it
%   subscribes to, in order.  Content is [] for `fact_checking`
%   watchers, else the list of new (or removed) values.  The
%   subscriber belongs to the caller, who destroys it with
%   oro_subscriber_destroy/1,2 (oro_events_reset/0 leaves it).
%   Options:
%
%     - max_queue(+N): firings waiting at most (default 10000); past it
%       the subscriber is dropped: it loses its subscriptions;
%     - on_overflow(:Goal): called (in a thread of its own) when it is
%       dropped;
%     - registry(+Registry): `plain` (default) or `agent`, which
%       clearEvents() and clearEventsForAgent() address apart, or
%       `internal`, which neither clears (oro's own watchers);
%     - in_watcher(+Bool): if `true`, Deliver is called directly by the
%       watcher thread, before the change is considered processed (see
%       oro_events_sync/0).  For oro's own short, non-blocking
%       reactions only, such as creating agent models.

oro_subscriber_create(Deliver, Subscriber, QOptions) :-
    strip_module(QOptions, _, Options0),
    must_be(list, Options0),
    meta_options(is_meta_option, QOptions, Options),
    subscriber_create(Deliver, Subscriber, Options, caller).

is_meta_option(on_overflow).

%   subscriber_create(:Deliver, -Subscriber, +Options, +Owner): Owner
%   is `caller` or `callback` (oro_subscribe/8: this module destroys it
%   on overflow and reset).

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
    with_mutex(oro_events,
               assertz(subscriber(Subscriber, Queue, Thread, Owner))).

subscriber_registry(subscriber(_, Registry, _), Registry) :-
    !.
subscriber_registry(Subscriber, _) :-
    type_error(oro_subscriber, Subscriber).

%!  oro_subscriber_destroy(+Subscriber) is det.
%!  oro_subscriber_destroy(+Subscriber, +Options) is det.
%
%   Unsubscribe Subscriber from every watcher (watchers left without
%   subscribers are dropped), deliver what it has queued and stop its
%   thread; nothing if it is destroyed already.  Called from its own
%   Deliver, what it has queued is discarded and its thread ends once
%   Deliver returns.  Options:
%
%     - abort(+Bool): if `true`, what it has queued is discarded and a
%       call of Deliver in progress is interrupted (by the exception
%       `oro_delivery_aborted`, which the thread handles), also out of
%       a blocked write: for a subscriber writing to a connection that
%       is closing.  Never for a planner's callback.

:- predicate_options(oro_subscriber_destroy/2, 2, [abort(boolean)]).

oro_subscriber_destroy(Subscriber) :-
    oro_subscriber_destroy(Subscriber, []).

oro_subscriber_destroy(Subscriber, Options) :-
    must_be(compound, Subscriber),
    must_be(list, Options),
    option(abort(Abort), Options, false),
    must_be(boolean, Abort),
    (   claim_subscriber(Subscriber, Queue, Thread)
    ->  call_watcher(unsubscribe(Subscriber)),
        Subscriber = subscriber(Name, _, _),
        (   Queue = direct(_)
        ->  true
        ;   Abort == true
        ->  stop_delivery(Name, Queue, Thread, abort)
        ;   stop_delivery(Name, Queue, Thread, deliver)
        )
    ;   true
    ).

%   claim_subscriber(+Subscriber, -Queue, -Thread) is semidet: take
%   Subscriber out of the table of live subscribers.  Who claims it
%   (a destroy, a reset, an overflow) stops its thread; the watcher
%   thread sends nothing more to it.

claim_subscriber(Subscriber, Queue, Thread) :-
    with_mutex(oro_events,
               ( retract(subscriber(Subscriber, Queue, Thread, _)),
                 retractall(callback_subscriber(_, Subscriber))
               )).

%   stop_delivery(+Name, +Queue, +Thread, +How): end the delivery
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
    with_mutex(oro_events,
               (   discarding(Name)
               ->  true
               ;   assertz(discarding(Name))
               )).

end_delivery(Name, Queue) :-
    message_queue_destroy(Queue),
    with_mutex(oro_events, retractall(discarding(Name))).

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

:- predicate_options(oro_subscribe/8, 8,
                     [ max_queue(positive_integer),
                       on_overflow(callable)
                     ]).

%!  oro_subscribe(+Model, +Type, +Trigger, +Var, +Patterns, :Callback,
%!                -Id) is det.
%
%   As oro_subscribe/8 with no options, giving the watcher id; stop it
%   with oro_unsubscribe(Id), which stops every callback on that
%   watcher.

oro_subscribe(Model, Type, Trigger, Var, Patterns, Callback, Id) :-
    oro_subscribe(Model, Type, Trigger, Var, Patterns, Callback,
                  oro_subscription(Id, _), []).

%!  oro_subscribe(+Model, +Type, +Trigger, +Var, +Patterns, :Callback,
%!                -Subscription, +Options) is det.
%
%   Register a watcher (see oro_register_event/7) whose firings call
%   call(Callback, Id, Content) in a thread of its own, in order: the
%   Prolog equivalent of registerEvent for a planner in the same
%   process.  Subscription is oro_subscription(Id, Ref): Id is the
%   watcher id, which Callback receives and identical subscriptions
%   share; the whole term is this subscription's own handle for
%   oro_unsubscribe/1.  Options:
%
%     - max_queue(+N): firings waiting for Callback at most (default
%       10000).  Past it the subscription is dropped: it is
%       unsubscribed, its queued firings are discarded, its thread ends
%       once a call of Callback in progress returns, and its
%       on_overflow goal is told.
%     - on_overflow(:Goal): called as call(Goal, Subscription), in a
%       thread of its own, when the subscription is dropped; Callback
%       is not called for any later firing.  A planner may subscribe
%       anew from there.
%
%   oro_reset/0 destroys every subscription.

oro_subscribe(Model, Type, Trigger, Var, Patterns, Callback, Subscription,
              QOptions) :-
    strip_module(QOptions, _, Options0),
    must_be(list, Options0),
    meta_options(is_meta_option, QOptions, Options1),
    include(subscribe_option, Options1, Options),
    subscriber_create(Callback, Subscriber, Options, callback),
    catch(oro_register_event(Model, Type, Trigger, Var, Patterns,
                             Subscriber, Id),
          E,
          ( oro_subscriber_destroy(Subscriber),
            throw(E)
          )),
    Subscription = oro_subscription(Id, Subscriber).

subscribe_option(max_queue(_)).
subscribe_option(on_overflow(_)).

%!  oro_unsubscribe(+IdOrSubscription) is det.
%
%   Stop callbacks set by oro_subscribe/7,8: given a Subscription
%   handle, that subscription only (others on the same watcher go on);
%   given a watcher Id, every callback on that watcher, whoever set it.
%   When this returns the callbacks stopped have received what was
%   queued for them and are not running (unless called from one of
%   them, which then ends once it returns).  Nothing if they are
%   stopped already.

oro_unsubscribe(Subscription) :-
    compound(Subscription),
    Subscription = oro_subscription(_, Subscriber),
    !,
    oro_subscriber_destroy(Subscriber).
oro_unsubscribe(Id) :-
    must_be(atom, Id),
    with_mutex(oro_events,
               findall(S, callback_subscriber(Id, S), Subscribers)),
    maplist(oro_subscriber_destroy, Subscribers).

		 /*******************************
		 *        WATCHER THREAD        *
		 *******************************/

%   The watcher thread passes a closed rebuild gate (oro_store_read/1):
%   a rebuild waits for it to process every change, and the writes of
%   its in-watcher callbacks (agent models) are part of that.

watcher_start :-
    oro_store_gate_exempt,
    watcher_loop.

watcher_loop :-
    thread_get_message(oro_watcher_queue, Message),
    catch(( handle(Message),
            collect_dropped,
            warm_while_idle
          ),
          E, handle_error(E)),
    watcher_loop.

%   warm_while_idle: while no message waits, compile the shared schema
%   tables of the models that have none for the current generation,
%   one model at a time (`myself` first).  It stops when every model
%   has them, and when a compilation did not give a model current
%   tables (a schema change started meanwhile): once that change is
%   over, its schema_changed message (see below) starts it again, so a
%   long schema-changing write is not met with compilation after
%   compilation.  It reads the store through the rebuild gate, without
%   waiting (oro_store_try_read/1): a store rebuild must not reset
%   rdf_db under it, and sends schema_changed once it is over.

warm_while_idle :-
    (   setting(warm_schemas, true),
        \+ thread_peek_message(oro_watcher_queue, _),
        cold_model(Model)
    ->  (   oro_store_try_read(oro_shared_schema(Model, _)),
            oro_compiled_schema(Model, _)
        ->  debug(oro(events), 'Schema tables of ~q compiled ahead', [Model]),
            warm_while_idle
        ;   true
        )
    ;   true
    ).

cold_model(Model) :-
    (   Model = myself,
        oro_model(myself)
    ;   oro_model(Model),
        Model \== myself
    ),
    \+ oro_compiled_schema(Model, _),
    !.

%   How many watchers there are is counted (the flag
%   oro_events_watchers) by this thread, which alone asserts and
%   retracts watcher/5: the writers' monitor asks for every triple
%   (watching/0).  Asking watcher/5 itself would cost time in
%   proportion to the watchers dropped so far: SWI-Prolog keeps a
%   retracted clause, which lookups step over, until its clause garbage
%   collector runs, and it looks past the first clause for another one.
%   The collector starts by itself only when the retracted clauses
%   weigh enough against all the program's clauses, which a store's
%   name index makes large.  So the watcher thread runs the collector
%   itself once max_dropped/1 watchers were dropped since it last did.
%   What the dropped watchers cost before (a scratch script, and
%   bench_full's adds with two requests in flight, which it measures
%   after registering and clearing 2,000 watchers) is in
%   the history of bench/RESULTS.md (git log), "Dropped watchers left work behind".

watching :-
    flag(oro_events_watchers, N, N),
    N > 0.

max_dropped(32).

collect_dropped :-
    flag(oro_events_dropped, Dropped, Dropped),
    (   max_dropped(Max),
        Dropped >= Max
    ->  flag(oro_events_dropped, _, 0),
        garbage_collect_clauses
    ;   true
    ).

%   An error is reported and the thread goes on with the next message;
%   an abort (the process halting) ends it quietly.

handle_error(E) :-
    rethrow_abort(E),
    print_message(error, E).

rethrow_abort(E) :-
    (   ( E == '$aborted' ; E = unwind(_) )
    ->  throw(E)
    ;   true
    ).

handle(change(Snapshot, Touched, Schema, Delta)) :-
    call_cleanup(process_change(Snapshot, Touched, Schema, Delta),
                 ( rdf_delete_snapshot(Snapshot),
                   (   Schema == true
                   ->  flag(oro_events_pending, N, N-1)
                   ;   true
                   )
                 )),
    run_direct_deliveries.
handle(warm(Model)) :-                 % compiled unless already done
    ignore(oro_store_try_read(oro_shared_schema(Model, _))).
handle(schema_changed).                 % warm_while_idle/0 follows
handle(call(Request, Thread, Tag)) :-
    (   catch(request(Request, Result0), E, (Result0 = error(E)))
    ->  Result = Result0
    ;   Result = error(failed(Request))
    ),
    catch(thread_send_message(Thread, reply(Tag, Result)),
          error(existence_error(thread, _), _),
          true).                        % the caller is gone

%   Deliveries to in_watcher subscribers run once the snapshot
%   transaction is over, so they may change the store.

run_direct_deliveries :-
    forall(retract(pending_direct(Deliver, Id, Content)),
           catch(call(Deliver, Id, Content), E,
                 print_message(warning, E))).

request(sync, true).
request(reset, stop(Stops)) :-
    aggregate_all(count, watcher(_, _, _, _, _), Count),
    retractall(watcher(_, _, _, _, _)),
    flag(oro_events_watchers, _, 0),
    flag(oro_events_dropped, Dropped, Dropped+Count),
    retractall(watcher_variant(_, _)),
    retractall(watcher_seq(_, _)),
    retractall(watcher_state(_, _)),
    retractall(watcher_value(_, _)),
    retractall(watcher_dep(_, _, _)),
    retractall(watcher_trigger(_, _, _, _, _)),
    retractall(watcher_type_class(_, _, _)),
    retractall(watcher_type_open(_, _)),
    retractall(watcher_plan(_, _)),
    retractall(subscription(_, _)),
    forall(retract(model_schema(_, Key)), oro_drop_schema(Key)),
    findall(S, subscriber(S, _, _, callback), Subscribers),
    findall(stop(Name, Queue, Thread),
            ( member(S, Subscribers),
              S = subscriber(Name, _, _),
              claim_subscriber(S, Queue, Thread)
            ), Stops).
request(register(Model, Registry, Spec, Query, Subscriber, Snapshot), id(Id)) :-
    call_cleanup(register(Model, Registry, Spec, Query, Subscriber,
                          Snapshot, Id),
                 ( rdf_delete_snapshot(Snapshot),
                   flag(oro_events_pending, N, N-1)
                 )).
request(clear(Model, Registry), true) :-
    forall(watcher(Id, Model, Registry, _, _), drop_watcher(Id)).
request(clear_one(Model, Registry, Id), true) :-
    (   watcher(Id, Model, Registry, _, _)
    ->  drop_watcher(Id)
    ;   existence_error(event, Id)
    ).
request(unsubscribe(Subscriber), true) :-
    unsubscribe(Subscriber).

register(_, _, _, _, Subscriber, _, _) :-
    \+ subscriber(Subscriber, _, _, _),
    !,
    existence_error(oro_subscriber, Subscriber).    % destroyed meanwhile
register(Model, Registry, Spec, _, Subscriber, _, Id) :-
    variant_key(Model, Registry, Spec, Key),
    watcher_variant(Key, Id),
    watcher(Id, Model, Registry, Spec0, _),
    Spec0 =@= Spec,                     % the same: term patterns have variables
    !,
    (   subscription(Id, Subscriber)
    ->  true
    ;   assertz(subscription(Id, Subscriber))
    ),
    note_callback(Id, Subscriber).
register(Model, Registry, Spec, Query, Subscriber, Snapshot, Id) :-
    uuid(Id, [version(4)]),
    rdf_transaction(ensure_schemas([Model]), oro(events), [snapshot(Snapshot)]),
    in_snapshot(Snapshot, [Model],
                ( initial_state(Spec, Model, Query, State, Values),
                  watcher_index(Spec, Model, Query, State, Index)
                )),
    flag(oro_watcher_seq, Seq, Seq+1),
    assertz(watcher(Id, Model, Registry, Spec, Query)),
    variant_key(Model, Registry, Spec, Key),
    assertz(watcher_variant(Key, Id)),
    flag(oro_events_watchers, N, N+1),
    assertz(watcher_seq(Id, Seq)),
    assertz(watcher_state(Id, State)),
    forall(member(V, Values), assertz(watcher_value(V, Id))),
    set_index(Id, Model, Index),
    assertz(subscription(Id, Subscriber)),
    note_callback(Id, Subscriber),
    debug(oro(events), 'Watcher ~w: ~q', [Id, Spec]).

%   variant_key(+Model, +Registry, +Spec, -Key): the key under which
%   watcher_variant/2 finds the watchers identical to Spec (its
%   variants: term patterns have variables) of Model in Registry, so
%   that a registration joins an identical watcher in one hashed lookup
%   whatever the number of watchers; the candidates it finds are
%   compared with =@=/2.  Attributes of the variables are ignored.

variant_key(Model, Registry, Spec, Key) :-
    copy_term_nat(Spec, Plain),
    variant_sha1(v(Model, Registry, Plain), Key).

%   note_callback(+Id, +Subscriber): a subscriber of oro_subscribe/8 is
%   noted with its watcher here, in the watcher thread, so that an
%   overflow right after the registration finds it.

note_callback(Id, Subscriber) :-
    (   subscriber(Subscriber, _, _, callback),
        \+ callback_subscriber(Id, Subscriber)
    ->  with_mutex(oro_events, assertz(callback_subscriber(Id, Subscriber)))
    ;   true
    ).

%   The initial state: fact_checking watchers start `unknown` (false)
%   and are not evaluated (ORO-SPEC §7.3); the others remember their
%   current values.

initial_state(spec(fact_checking, _, _, _), _, _, unknown, []) :- !.
initial_state(_, Model, Query, values, Values) :-
    query_values(Model, Query, Values).

drop_watcher(Id) :-
    (   retract(watcher(Id, Model, Registry, Spec, _))
    ->  variant_key(Model, Registry, Spec, Key),
        retractall(watcher_variant(Key, Id)),
        flag(oro_events_watchers, N, N-1),
        flag(oro_events_dropped, D, D+1)
    ;   true
    ),
    retractall(watcher_seq(Id, _)),
    retractall(watcher_state(Id, _)),
    retractall(watcher_value(_, Id)),
    retractall(watcher_dep(_, _, Id)),
    retractall(watcher_trigger(_, _, _, _, Id)),
    retractall(watcher_type_class(_, _, Id)),
    retractall(watcher_type_open(_, Id)),
    retractall(watcher_plan(Id, _)),
    retractall(subscription(Id, _)).

drop_if_orphan(Id) :-
    (   subscription(Id, _)
    ->  true
    ;   drop_watcher(Id)
    ).

%   in_snapshot(+Snapshot, +Models, :Goal): run Goal in the snapshot,
%   with the schemas the watcher thread compiled for Models.

in_snapshot(Snapshot, Models, Goal) :-
    rdf_transaction(with_schemas(Models, Goal), oro(events), [snapshot(Snapshot)]).

with_schemas(Models, Goal) :-
    findall(M-K, ( member(M, Models), model_schema(M, K) ), Keys),
    oro_with_schemas(Keys, Goal).

		 /*******************************
		 *            INDEX             *
		 *******************************/

%!  watcher_index(+Spec, +Model, +Query, +State, -Index) is det.
%
%   Index is index(Deps, Triggers, Plan) for a watcher, computed with
%   the schema of Model (see the module doc):
%
%     - Deps: `[any]` or the predicates whose triples may change it;
%     - Triggers: Predicate-Anchor pairs, Anchor `none`, res(R),
%       class(C), or `chain` and chain(C) for a pattern through a
%       transitive property (chain_watcher/6) (none when Deps is
%       `[any]`);
%     - Plan: `full`, `static` (a new_instance watcher whose variable
%       is not in its patterns) or items(Items), one
%       item(I, Kind, PDeps, Anchored) per pattern: its index I, its
%       Kind (`step`, `type` or trans(Transitives)), its own
%       dependencies (`any` or an ordset) and whether the template
%       variable is its subject or object (`true` or `false`).

watcher_index(Spec, Model, query(Template, Triples), State, index(Deps, Triggers, Plan)) :-
    watcher_deps(Spec, Model, Triples, State, Deps),
    watcher_plan(Spec, Model, Template, Triples, Plan),
    (   Deps == [any]
    ->  Triggers = []
    ;   Plan = items(Items)
    ->  findall(Q-Anchor, ( member(Item, Items),
                            item_trigger(Item, Triples, Q, Anchor)
                          ), Triggers0),
        sort(Triggers0, Triggers)
    ;   findall(Q-none, member(Q, Deps), Triggers)
    ).

%   A fact_checking watcher not evaluated yet depends on any change (it
%   fires at the first one if already true); so do one-shot triggers
%   without edge detection, which fire at any change (ORO-SPEC §7.3).

watcher_deps(spec(fact_checking, Trigger, _, _), _, _, State, [any]) :-
    (   State == unknown
    ;   memberchk(Trigger, [on_true_one_shot, on_false_one_shot])
    ),
    !.
watcher_deps(_, Model, Triples, _, Deps) :-
    oro_pattern_dependencies(Model, Triples, Deps).

watcher_plan(spec(new_instance, _, _, _), _, Template, _, static) :-
    nonvar(Template),
    !.
watcher_plan(_, Model, Template, Triples, Plan) :-
    findall(Item, ( nth1(I, Triples, Triple),
                    pattern_item(Model, Template, I, Triple, Item)
                  ), Items),
    (   memberchk(item(_, full, _, _), Items)
    ->  Plan = full
    ;   Plan = items(Items)
    ).

pattern_item(Model, Template, I, rdf(S, P, O), item(I, Kind, Deps, Anchored)) :-
    oro_pattern_dependencies(Model, [rdf(S, P, O)], Deps0),
    (   Deps0 == [any]
    ->  Deps = any
    ;   Deps = Deps0
    ),
    pattern_kind(Model, S, P, O, Deps, Kind),
    (   var(Template),
        anchored(Kind, Template, S, O)
    ->  Anchored = true
    ;   Anchored = false
    ).

%   pattern_kind(+Model, +S, +P, +O, +Deps, -Kind): how the instances a
%   change creates are found (see the module doc).  A type with both
%   ends unbound is evaluated in full: solved unbound it only ranges
%   over individuals, while a seeded subject could be a class.  So is a
%   pattern whose subject and object are one variable (`?x near ?x`):
%   solved unbound, owl:sameAs substitution does not check that both
%   ends are the same individual, seeded it does.

pattern_kind(_, _, P, _, _, full) :-
    var(P),
    !.
pattern_kind(_, S, _, O, _, full) :-
    var(S),
    S == O,
    !.
pattern_kind(_, S, P, O, _, Kind) :-
    rdf_equal(P, rdf:type),
    !,
    (   var(S),
        var(O)
    ->  Kind = full
    ;   Kind = type
    ).
pattern_kind(_, _, P, _, _, full) :-
    special_predicate(P),
    !.
pattern_kind(_, _, _, _, any, full) :-
    !.
pattern_kind(Model, _, _, _, Deps, Kind) :-
    findall(T-TDeps, ( member(T, Deps),
                       oro_transitive_property(Model, T),
                       oro_pattern_dependencies(Model, [rdf(_, T, _)], TDeps)
                     ), Transitives),
    (   Transitives == []
    ->  Kind = step
    ;   Kind = trans(Transitives)
    ).

:- rdf_meta special_predicate(r).

special_predicate(rdfs:subClassOf).
special_predicate(rdfs:subPropertyOf).
special_predicate(owl:sameAs).

anchored(step, Template, S, O) :-
    (   Template == S
    ->  true
    ;   Template == O
    ).
anchored(type, Template, S, _) :-
    Template == S.

%   item_trigger(+Item, +Triples, -Q, -Anchor): a change of a triple
%   with predicate Q mentioning Anchor may change the pattern of Item.

item_trigger(item(I, Kind, Deps, _), Triples, Q, Anchor) :-
    Deps \== any,
    nth1(I, Triples, rdf(S, _, O)),
    member(Q, Deps),
    item_anchor(Kind, Q, S, O, Anchor).

item_anchor(step, _, S, O, Anchor) :-
    !,
    (   atom(S)
    ->  Anchor = res(S)
    ;   atom(O)
    ->  Anchor = res(O)
    ;   Anchor = none
    ).
item_anchor(type, Q, S, O, Anchor) :-
    !,
    (   atom(S)
    ->  Anchor = res(S)
    ;   atom(O),
        rdf_equal(Q, rdf:type)
    ->  Anchor = class(O)
    ;   Anchor = none
    ).
item_anchor(trans(Transitives), Q, S, O, Anchor) :-
    (   atom(S)
    ->  C = S
    ;   atom(O)
    ->  C = O
    ),
    !,
    (   member(_-TDeps, Transitives),
        ord_memberchk(Q, TDeps)
    ->  (   Anchor = chain
        ;   Anchor = chain(C)
        )
    ;   Anchor = res(C)
    ).
item_anchor(_, _, _, _, none).

%   set_index(+Id, +Model, +Index): install the index of watcher Id.
%   New dependencies are added before the old ones go: writers read
%   them (touch/5) to decide whether to send a change, and must
%   never see a watcher with none.  Triggers and plans are the watcher
%   thread's own.

set_index(Id, Model, index(Deps, Triggers, Plan)) :-
    findall(D, watcher_dep(Model, D, Id), Old),
    forall(( member(D, Deps), \+ memberchk(D, Old) ),
           assertz(watcher_dep(Model, D, Id))),
    forall(( member(D, Old), \+ memberchk(D, Deps) ),
           retractall(watcher_dep(Model, D, Id))),
    set_type_triggers(Id, Model, Triggers),
    retractall(watcher_trigger(_, _, _, _, Id)),
    forall(( member(Q-Anchor, Triggers),
             Anchor \= class(_)
           ),
           ( trigger_key(Model, Q, Anchor, Key),
             assertz(watcher_trigger(Key, Model, Q, Anchor, Id))
           )),
    retractall(watcher_plan(Id, _)),
    assertz(watcher_plan(Id, Plan)).

%   set_type_triggers(+Id, +Model, +Triggers): the triggers of watcher Id
%   on rdf:type, which the writers read too (type_filter/3): a class(C)
%   anchor as watcher_type_class(C, Model, Id) (class_watcher/4, the
%   only place class anchors are kept), any other as
%   watcher_type_open(Model, Id).  New facts are added before stale ones
%   go, as for the dependencies.

set_type_triggers(Id, Model, Triggers) :-
    rdf_equal(rdf:type, Type),
    findall(C, member(Type-class(C), Triggers), Classes0),
    sort(Classes0, Classes),
    (   member(Type-Anchor, Triggers),
        Anchor \= class(_)
    ->  Open = true
    ;   Open = false
    ),
    (   Open == true,
        \+ watcher_type_open(Model, Id)
    ->  assertz(watcher_type_open(Model, Id))
    ;   true
    ),
    forall(( member(C, Classes),
             \+ watcher_type_class(C, Model, Id)
           ),
           assertz(watcher_type_class(C, Model, Id))),
    forall(( watcher_type_class(C, Model, Id),
             \+ ord_memberchk(C, Classes)
           ),
           retractall(watcher_type_class(C, Model, Id))),
    (   Open == false
    ->  retractall(watcher_type_open(Model, Id))
    ;   true
    ).

trigger_key(Model, Q, Anchor, Key) :-
    term_hash(t(Model, Q, Anchor), Key).

		 /*******************************
		 *           CHANGES            *
		 *******************************/

process_change(Snapshot, Touched, Schema, Delta) :-
    setting(index, Index),
    (   (   Schema == true
        ;   Index == false                  % the reference mode
        )
    ->  forget_schemas(Touched)
    ;   true
    ),
    affected_models(Touched, Models),
    (   Models == []
    ->  true
    ;   setting(incremental, Incremental),
        rdf_transaction(change_in_snapshot(Models, Touched, Schema, Delta,
                                           Incremental-Index),
                        oro(events), [snapshot(Snapshot)])
    ).

%   After a schema change, the schemas the watcher thread compiled for
%   the models it touched are stale: they are compiled again, in the
%   snapshot of the next change or registration that needs them.

forget_schemas(Touched) :-
    (   memberchk('$all'-_, Touched)
    ->  forall(retract(model_schema(_, Key)), oro_drop_schema(Key))
    ;   forall(( member(M-_, Touched),
                 retract(model_schema(M, Key))
               ),
               oro_drop_schema(Key))
    ).

affected_models(Touched, Models) :-
    (   memberchk('$all'-_, Touched)
    ->  findall(M, watcher(_, M, _, _, _), Models0)
    ;   findall(M, ( member(M-_, Touched),
                     once(watcher(_, M, _, _, _))
                   ), Models0)
    ),
    sort(Models0, Models).

change_in_snapshot(Models, Touched, Schema, Delta, How) :-
    ensure_schemas(Models),
    with_schemas(Models,
                 forall(member(Model, Models),
                        evaluate_model(Model, Touched, Schema, Delta, How))).

ensure_schemas(Models) :-
    forall(( member(M, Models),
             \+ model_schema(M, _)
           ),
           ( oro_compile_schema(M, Key),
             assertz(model_schema(M, Key))
           )).

%   evaluate_model(+Model, +Touched, +Schema, +Delta,
%                  +Incremental-Index): evaluate the watchers of Model
%   the change may affect, in registration order: all of them after a
%   schema change, or in the reference mode (Index `false`).  Mode is
%   `full` or delta(Added, Removed, Same), the triples of the change in
%   Model.

evaluate_model(Model, Touched, Schema, Delta, Incremental-Index) :-
    (   (   Schema == true
        ;   Index == false
        )
    ->  findall(Id, watcher(Id, Model, _, _, _), Ids0),
        Mode = full
    ;   Incremental == true,
        Delta \== full,
        \+ memberchk('$all'-_, Touched)
    ->  model_delta(Model, Delta, Added, Removed, Same),
        Mode = delta(Added, Removed, Same),
        triggered_watchers(Model, Added, Removed, Same, Ids0)
    ;   findall(Id, ( watcher_dep(Model, any, Id)
                    ; ( member(Model-P, Touched)
                      ; member('$all'-P, Touched)
                      ),
                      watcher_dep(Model, P, Id)
                    ), Ids0),
        Mode = full
    ),
    by_registration(Ids0, Ids),
    debug(oro(events), 'Change of ~q: ~q', [Model, watchers(Ids)]),
    forall(member(Id, Ids), guarded_evaluation(Id, Mode, Schema)).

%   guarded_evaluation(+Id, +Mode, +Schema): evaluate_watcher/3, for
%   one watcher alone.  A watcher whose evaluation raises an error (its
%   query ran over the `oro_query:time_limit`, say: a pattern joining
%   unrelated variables over a large store) is dropped, and the server
%   says so in its log; the other watchers of the change are evaluated
%   as usual.  Kept, it would raise again at each change, and hold up
%   every other subscriber's events for as long each time.

guarded_evaluation(Id, Mode, Schema) :-
    catch(evaluate_watcher(Id, Mode, Schema), E,
          watcher_failed(Id, E)).

watcher_failed(Id, E) :-
    rethrow_abort(E),
    print_message(warning, oro_watcher_dropped(Id)),
    print_message(warning, E),
    drop_watcher(Id).

:- multifile prolog:message//1.

prolog:message(oro_watcher_dropped(Id)) -->
    [ 'Event ~w dropped: its evaluation raised the error below'-[Id] ].

%   model_delta(+Model, +Delta, -Added, -Removed, -Same): the triples
%   of Delta added to and removed from Model, as ordered sets of
%   t(S, P, O), and an assoc from their resources to their owl:sameAs
%   individuals (themselves included), looked up once a change.

model_delta(Model, Delta, Added, Removed, Same) :-
    findall(t(S, P, O), member(d(Model, add, S, P, O), Delta), Added0),
    sort(Added0, Added),
    findall(t(S, P, O), member(d(Model, del, S, P, O), Delta), Removed0),
    sort(Removed0, Removed),
    (   oro_has_same_individuals(Model)
    ->  findall(X, ( member(d(Model, _, S, _, O), Delta),
                     (   X = S
                     ;   X = O
                     ),
                     atom(X)
                   ), Resources0),
        sort(Resources0, Resources),
        findall(X-Ys, ( member(X, Resources),
                        findall(Y, oro_same_individual(Model, X, Y), Ys)
                      ), Pairs),
        list_to_assoc(Pairs, Same)
    ;   empty_assoc(Same)                   % each individual is itself only
    ).

%   triggered_watchers(+Model, +Added, +Removed, -Ids): the watchers
%   depending on any change, and those a trigger of a changed triple
%   names: by predicate alone, by a resource of the triple (or one of
%   its owl:sameAs individuals) or, for a type, by a super class.

triggered_watchers(Model, Added, Removed, Same, Ids) :-
    findall(Id, ( watcher_dep(Model, any, Id)
                ; ( member(t(S, P, O), Added)
                  ; member(t(S, P, O), Removed)
                  ),
                  triggered(Model, Same, S, P, O, Id)
                ), Ids).

triggered(Model, Same, S, P, O, Id) :-
    (   triple_anchor(Same, S, O, Anchor),
        trigger_key(Model, P, Anchor, Key),
        watcher_trigger(Key, Model, P, Anchor, Id)
    ;   rdf_equal(P, rdf:type),
        model_schema(Model, SchemaKey),
        class_watcher(SchemaKey, Model, O, Id)
    ;   chain_watcher(Model, Same, S, P, O, Id)
    ).

triple_anchor(_, _, _, none).
triple_anchor(Same, S, O, res(R)) :-
    (   X = S
    ;   X = O
    ),
    atom(X),
    same_individual(Same, X, R).

%   chain_watcher(+Model, +Same, +S, +P, +O, -Id): watcher Id has a
%   pattern through a transitive property T (Kind trans(_), see
%   item_anchor/5) whose constant end is among the resources a triple
%   `S P O`, P a dependency of T, can join to a new (or lost) instance:
%   what reaches S or O through T and what they reach, themselves and
%   their owl:sameAs individuals included (the ends chain_ends/8 seeds
%   from).  Such a watcher is anchored by chain(C), C its constant, and
%   by `chain`, which selects every one of them on P when the ends are
%   more than max_seeds/1 (as every change of P did before).  A lost
%   instance A T B used a removed triple: the first removed one on its
%   path, u-v, has A among what reaches u after the change, the last
%   one has B among what v reaches.

chain_watcher(Model, Same, S, P, O, Id) :-
    trigger_key(Model, P, chain, AnyKey),
    once(watcher_trigger(AnyKey, Model, P, chain, _)),
    chain_anchors(Model, Same, S, P, O, Anchors),
    length(Anchors, N),
    max_seeds(Max),
    (   N =< Max
    ->  member(C, Anchors),
        trigger_key(Model, P, chain(C), Key),
        watcher_trigger(Key, Model, P, chain(C), Id)
    ;   watcher_trigger(AnyKey, Model, P, chain, Id)
    ).

chain_anchors(Model, Same, S, P, O, Anchors) :-
    findall(C, ( oro_transitive_property(Model, T),
                 oro_pattern_dependencies(Model, [rdf(_, T, _)], TDeps),
                 ord_memberchk(P, TDeps),
                 (   X = S
                 ;   X = O
                 ),
                 atom(X),
                 (   same_individual(Same, X, C)
                 ;   oro_holds(Model, C, T, X)
                 ;   oro_holds(Model, X, T, C)
                 )
               ), Anchors0),
    sort(Anchors0, Anchors).

%   class_watcher(+SchemaKey, +Model, +Class, -Id): watcher Id of Model is
%   anchored by a super-class of Class (in the schema tables SchemaKey):
%   a triple `s rdf:type Class` may change it.  The watcher thread asks
%   it with the schema of the change (triggered/6), the writers with the
%   shared one (triple_followed/5).

class_watcher(SchemaKey, Model, Class, Id) :-
    atom(Class),
    oro_schema_superclass(SchemaKey, Class, Super),
    watcher_type_class(Super, Model, Id).

%   Watchers are evaluated in the order they were registered, so that
%   two firings of one change reach a subscriber in a stable order.

by_registration(Ids0, Ids) :-
    findall(Seq-Id, ( member(Id, Ids0),
                      watcher_seq(Id, Seq)
                    ), Pairs0),
    sort(Pairs0, Pairs),
    pairs_values(Pairs, Ids).

evaluate_watcher(Id, Mode, Schema) :-
    watcher(Id, Model, _, Spec, Query),
    watcher_state(Id, State0),
    !,
    outcome(Mode, Id, Spec, Model, Query, State0, Outcome),
    Spec = spec(Type, Trigger, _, _),
    apply_outcome(Outcome, Id, State0, State),
    firings(Type, Trigger, State0, Outcome, Contents, Remove),
    forall(member(Content, Contents), fire(Id, Content)),
    (   Remove == true
    ->  drop_watcher(Id)
    ;   \+ watcher(Id, _, _, _, _)
    ->  true                                % its subscribers were dropped
    ;   (   Schema == true
        ;   State0 == unknown
        )
    ->  watcher_index(Spec, Model, Query, State, Index),
        set_index(Id, Model, Index)
    ;   true
    ).
evaluate_watcher(_, _, _).                  % dropped meanwhile

%   outcome(+Mode, +Id, +Spec, +Model, +Query, +State0, -Outcome): the
%   new truth(Bool) of a fact_checking watcher, or diff(Added,
%   Removed) of the values of the others (ordered sets), evaluated
%   from the change's triples where the plan allows, else in full.

outcome(delta(Added, Removed, Same), Id, Spec, Model, Query, State0, Outcome) :-
    watcher_plan(Id, Plan),
    catch(delta_outcome(Plan, Spec, Id, Model-Same, Query, State0,
                        Added, Removed, Outcome0),
          oro_events_full, fail),
    !,
    debug(oro(events), 'Watcher ~w: from the change, ~q', [Id, Outcome0]),
    Outcome = Outcome0.
outcome(_, Id, Spec, Model, Query, _, Outcome) :-
    full_outcome(Spec, Id, Model, Query, Outcome),
    debug(oro(events), 'Watcher ~w: in full, ~q', [Id, Outcome]).

full_outcome(spec(fact_checking, _, _, _), _, Model, query(_, Triples), truth(Truth)) :-
    !,
    (   \+ \+ oro_solve(Model, Triples)
    ->  Truth = true
    ;   Truth = false
    ).
full_outcome(_, Id, Model, Query, diff(Added, Removed)) :-
    query_values(Model, Query, Now),
    findall(V, watcher_value(V, Id), Old0),
    sort(Old0, Old),
    ord_subtract(Now, Old, Added),
    ord_subtract(Old, Now, Removed).

query_values(Model, query(Template, Triples), Values) :-
    (   var(Template)
    ->  oro_find_values(Model, Template, Triples, Values)
    ;   Values = []
    ).

apply_outcome(truth(Truth), Id, _, truth(Truth)) :-
    retractall(watcher_state(Id, _)),
    assertz(watcher_state(Id, truth(Truth))).
apply_outcome(diff(Added, Removed), Id, State, State) :-
    forall(member(V, Removed), retractall(watcher_value(V, Id))),
    forall(member(V, Added), assertz(watcher_value(V, Id))).

		 /*******************************
		 *         INCREMENTAL          *
		 *******************************/

%   delta_outcome(+Plan, +Spec, +Id, +Ctx, +Query, +State0, +Added,
%                 +Removed, -Outcome) is semidet.
%
%   The outcome of the change from its triples, in the new state; Ctx
%   is Model-Same, Same as made by model_delta/5.  Fails, or throws
%   oro_events_full, when the watcher must be evaluated in full.

delta_outcome(static, _, _, _, _, _, _, _, diff([], [])).
delta_outcome(items(Items), Spec, Id, Ctx, Query, State0, Added, Removed,
              Outcome) :-
    State0 \== unknown,
    concerned(Items, Added, AddPairs),
    concerned(Items, Removed, RemovePairs),
    (   Spec = spec(fact_checking, _, _, _)
    ->  truth_outcome(State0, Ctx, Query, AddPairs, RemovePairs, Outcome)
    ;   lost_values(RemovePairs, Id, Ctx, Query, Lost),
        new_values(AddPairs, Id, Ctx, Query, New),
        Outcome = diff(New, Lost)
    ).

%   concerned(+Items, +Triples, -Pairs): Item-Triple for each pattern
%   and changed triple whose predicate it depends on.

concerned(_, [], []) :-
    !.
concerned(Items, Triples, Pairs) :-
    findall(Item-t(S, P, O),
            ( member(t(S, P, O), Triples),
              member(Item, Items),
              item_depends(Item, P)
            ), Pairs).

item_depends(item(_, _, any, _), _) :-
    !.
item_depends(item(_, _, Deps, _), P) :-
    ord_memberchk(P, Deps).

%   A true conjunction stays true when triples are only added; a false
%   one becomes true only through a seeded solution.

truth_outcome(truth(true), _, _, _, RemovePairs, truth(true)) :-
    RemovePairs == [].
truth_outcome(truth(false), Ctx, Query, AddPairs, _, truth(Truth)) :-
    (   AddPairs == []
    ->  Truth = false
    ;   seeds(AddPairs, Ctx, Query, Seeds),
        (   seeded_solution(Seeds, Ctx, Query)
        ->  Truth = true
        ;   Truth = false
        )
    ).

%   lost_values(+RemovePairs, +Id, +Ctx, +Query, -Lost): the values no
%   longer holding.  A lost value is the subject or object (or one of
%   their sameAs individuals) of a removed triple when the template is
%   the subject or object of every pattern concerned; otherwise any
%   value may be lost, and the watcher is evaluated in full.

lost_values([], _, _, _, []) :-
    !.
lost_values(RemovePairs, Id, Model-Same, Query, Lost) :-
    \+ memberchk(item(_, _, _, false)-_, RemovePairs),
    findall(V, ( member(_-t(S, _, O), RemovePairs),
                 (   X = S
                 ;   X = O
                 ),
                 same_individual(Same, X, V),
                 watcher_value(V, Id)
               ), Candidates0),
    sort(Candidates0, Candidates),
    exclude(value_holds(Model, Query), Candidates, Lost).

%   value_holds(+Model, +Query, +Value): Value is still a value of the
%   template, as a full evaluation finds them.  A literal in a pattern
%   matches the literals of equal value (3 matches 3.0), while the
%   values found are the literals themselves: a literal that holds so
%   is checked again among the values the patterns give.

value_holds(Model, Query, Value) :-
    copy_term(Query, query(Value, Triples)),
    \+ \+ oro_solve(Model, Triples),
    (   Value = literal(_)
    ->  copy_term(Query, query(Template, AnyTriples)),
        \+ \+ ( oro_solve(Model, AnyTriples),
                Template == Value
              )
    ;   true
    ).

new_values([], _, _, _, []) :-
    !.
new_values(AddPairs, Id, Ctx, Query, New) :-
    seeds(AddPairs, Ctx, Query, Seeds),
    Ctx = Model-_,
    findall(V, ( member(Seed, Seeds),
                 seeded_query(Seed, Query, Template, Triples),
                 oro_find_values(Model, Template, Triples, Vs),
                 member(V, Vs),
                 \+ watcher_value(V, Id)
               ), New0),
    sort(New0, New).

seeded_solution(Seeds, Model-_, Query) :-
    member(Seed, Seeds),
    seeded_query(Seed, Query, _, Triples),
    oro_solve(Model, Triples),
    !.

%   seeded_query(+Seed, +Query, -Template, -Triples): a copy of Query
%   with the subject and object of pattern I bound as Seed says.

seeded_query(seed(I, S1, O1), Query, Template, Triples) :-
    copy_term(Query, query(Template, Triples)),
    nth1(I, Triples, rdf(S, _, O)),
    bind(S, S1),
    bind(O, O1).

bind(Term, Value) :-
    (   var(Value)
    ->  true
    ;   var(Term)
    ->  Term = Value
    ;   true                                % checked by seed_fits/2
    ).

%   seeds(+AddPairs, +Ctx, +Query, -Seeds): seed(I, S, O) terms, the
%   subject and object pattern I may take in an instance the added
%   triples made true (O unbound for a type).  Throws oro_events_full
%   past max_seeds/1.

seeds(AddPairs, Ctx, query(_, Triples), Seeds) :-
    findall(seed(I, S1, O1),
            ( member(item(I, Kind, _, _)-t(S, P, O), AddPairs),
              nth1(I, Triples, rdf(PS, _, PO)),
              seed(Kind, Ctx, S, P, O, PS, PO, S1, O1)
            ), Seeds0),
    sort(Seeds0, Seeds),
    length(Seeds, N),
    max_seeds(Max),
    (   N =< Max
    ->  true
    ;   throw(oro_events_full)
    ).

seed(step, _-Same, S, _, O, PS, PO, S1, O1) :-
    step_seed(Same, S, O, PS, PO, S1, O1).
seed(type, _-Same, S, _, O, PS, _, S1, _) :-
    (   X = S
    ;   X = O
    ),
    atom(X),
    same_individual(Same, X, S1),
    seed_fits(PS, S1).
seed(trans(_), _-Same, S, _, O, PS, PO, S1, O1) :-
    step_seed(Same, S, O, PS, PO, S1, O1).
seed(trans(Transitives), Ctx, S, P, O, PS, PO, S1, O1) :-
    member(T-TDeps, Transitives),
    ord_memberchk(P, TDeps),
    (   X = S, Y = O
    ;   X = O, Y = S
    ),
    atom(X),
    atom(Y),
    chain_ends(Ctx, T, X, Y, PS, PO, S1, O1).

%   An instance made by a triple `s q o` without transitivity: its
%   subject and object are s and o, either way round, or their sameAs
%   individuals.

step_seed(Same, S, O, PS, PO, S1, O1) :-
    (   X = S, Y = O
    ;   X = O, Y = S
    ),
    atom(X),
    same_individual(Same, X, S1),
    seed_fits(PS, S1),
    same_individual(Same, Y, O1),
    seed_fits(PO, O1).

%   Through a transitive T, an edge X→Y makes A T B true for A reaching
%   X and B reached from Y (themselves included); the pattern's
%   instance is A-B or B-A.  Both sets are computed once, filtered by
%   the constants of the pattern, and must stay small.

chain_ends(Model-Same, T, X, Y, PS, PO, S1, O1) :-
    findall(A, ( same_individual(Same, X, A)
               ; oro_holds(Model, A, T, X)
               ), As0),
    sort(As0, As),
    findall(B, ( same_individual(Same, Y, B)
               ; oro_holds(Model, Y, T, B)
               ), Bs0),
    sort(Bs0, Bs),
    include(seed_fits(PS), As, SAs),
    include(seed_fits(PO), Bs, OBs),
    include(seed_fits(PS), Bs, SBs),
    include(seed_fits(PO), As, OAs),
    length(SAs, NSA),
    length(OBs, NOB),
    length(SBs, NSB),
    length(OAs, NOA),
    max_seeds(Max),
    (   NSA * NOB + NSB * NOA =< Max
    ->  true
    ;   throw(oro_events_full)
    ),
    (   member(S1, SAs),
        member(O1, OBs)
    ;   member(S1, SBs),
        member(O1, OAs)
    ).

%   seed_fits(+PatternTerm, +Value): Value may stand at a position of
%   the pattern holding PatternTerm: a variable, the same resource, or
%   a literal (compared by value when the pattern is solved).

seed_fits(Term, Value) :-
    (   var(Term)
    ->  true
    ;   Term == Value
    ->  true
    ;   Term = literal(_)
    ->  Value = literal(_)
    ).

%   same_individual(+Same, +X, -Y): Y is X or one of its sameAs
%   individuals (a literal is only itself).

same_individual(Same, X, Y) :-
    (   atom(X),
        get_assoc(X, Same, Ys)
    ->  member(Y, Ys)
    ;   Y = X
    ).

		 /*******************************
		 *           FIRINGS            *
		 *******************************/

%!  firings(+Type, +Trigger, +State0, +Outcome, -Contents, -Remove)
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

%   fire(+Id, +Content): queue the firing to every subscriber, without
%   ever waiting.  A full queue drops its subscriber.

fire(Id, Content) :-
    (   watcher(Id, Model, _, _, _)
    ->  forall(fired(Model, Id, Content), true)
    ;   true
    ),
    forall(subscription(Id, Subscriber),
           send_firing(Subscriber, Id, Content)).

:- multifile fired/3.

%!  fired(+Model, +Id, +Content) is nondet.
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

unsubscribe(Subscriber) :-
    forall(retract(subscription(Id, Subscriber)),
           drop_if_orphan(Id)).

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
    ->  with_mutex(oro_events,
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
