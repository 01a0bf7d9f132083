:- module(oro_events_monitor,
          [ monitor/1                   % +Event
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(lists)).
:- use_module(library(settings)).
:- use_module(library(oro/oro_names)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/reason/oro_reason)).
:- use_module(library(oro/events/oro_events_registry)).

/** <module> Events: the store monitor, in the writing thread

The rdf_monitor/2 callback (monitor/1) that oro_events_start/0
installs: run by the writing thread when a transaction commits, it
notes which models and predicates the transaction touched, whether the
schema changed, and the changed triples a watcher may follow (up to
max_delta/1 a transaction), and at the end of the transaction queues
one `change` message, with an rdf_db snapshot, to the watcher thread
(oro_events_eval).  It never evaluates anything; what the watchers
follow it reads from the registry (oro_events_registry).  What a
commit notes is the writing thread's own: global variables and a
message queue of its own, no shared state.
*/

%   The triples a transaction may change and still be evaluated from
%   its triples (a bound of incremental evaluation).

max_delta(1000).

		 /*******************************
		 *           MONITOR            *
		 *******************************/

%!  monitor(+Event) is det.
%
%   Called by rdf_db in the writing thread when a transaction commits
%   (installed by oro_events_start/0).  It must stay cheap and never
%   fail or throw.  What a commit notes is kept by the writing thread,
%   in its global variables (oro_events_in_commit, oro_events_touched,
%   oro_events_touched_schema, and the delta's size and overflow) and,
%   for the triples of the delta, in a message queue of its own (see
%   delta_queue/1), not in facts: a clause asserted and retracted by
%   every write, or every triple, is work for SWI-Prolog's clause
%   garbage collector, which then also runs atom GC (see oro_store,
%   "Writes leave no clause behind").

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
    setting(oro_events:incremental, true),
    setting(oro_events:index, true),
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
        ;   \+ setting(oro_events:index, true)           % the reference mode
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
