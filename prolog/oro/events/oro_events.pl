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
:- use_module(library(option)).
:- use_module(library(oro/oro_names)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/reason/oro_reason)).
:- use_module(library(oro/parse/oro_parse)).
:- use_module(library(oro/events/oro_events_registry)).
:- use_module(library(oro/events/oro_events_delivery)).
:- use_module(library(oro/events/oro_events_eval)).

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

## The parts

This module is the API: registration, clearing and listing of
watchers, subscribers and subscriptions, reset and sync.  The rest
lives in one module each under `library(oro/events/...)`:

  - oro_events_registry: the watchers' tables and their index (and
    the settings above);
  - oro_events_monitor: the rdf_monitor/2 callback in the writing
    thread;
  - oro_events_eval: the watcher thread, the evaluation of changes,
    incremental and in full;
  - oro_events_delivery: subscribers, their queues and threads, and
    the firings (including the multifile hook oro_events:fired/3).
*/

		 /*******************************
		 *        RESET AND SYNC        *
		 *******************************/

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
    callback_subscribers(Id, Subscribers),
    maplist(oro_subscriber_destroy, Subscribers).
